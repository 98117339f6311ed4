#include "pointer/depth_trend.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace projtrack {

namespace {

struct Point {
  double t, v;
};

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2) return *mid;
  return (*mid + *std::max_element(v.begin(), mid)) / 2;
}

// Least squares through the points (at least one); a single instant gives a flat line.
TrendLine least_squares(const std::vector<Point>& pts) {
  double tm = 0, vm = 0;
  for (const Point& p : pts) tm += p.t, vm += p.v;
  tm /= static_cast<double>(pts.size());
  vm /= static_cast<double>(pts.size());
  double stt = 0, stv = 0;
  for (const Point& p : pts) stt += (p.t - tm) * (p.t - tm), stv += (p.t - tm) * (p.v - vm);
  return {vm, stt > 0 ? stv / stt : 0.0, tm, NAN};
}

// 1.4826 × the median absolute residual of the points about `line`: σ for Gaussian scatter.
double scatter(const std::vector<Point>& pts, const TrendLine& line) {
  std::vector<double> r;
  r.reserve(pts.size());
  for (const Point& p : pts) r.push_back(std::abs(p.v - line.at(p.t)));
  return 1.4826 * median(std::move(r));
}

}  // namespace

void DepthTrend::add(double t, double v, double window, double guard) {
  samples_.push_back({t, v});
  while (!samples_.empty() && samples_.front().t < t - window - guard) samples_.pop_front();
}

std::optional<TrendLine> DepthTrend::fit(double t, double guard, double settle) const {
  std::vector<Point> pts;
  for (const Sample& s : samples_)
    if (s.t <= t - guard) pts.push_back({s.t, s.v});
  if (pts.size() < 5 || pts.back().t - pts.front().t < settle) return std::nullopt;
  TrendLine line = least_squares(pts);
  line.noise = scatter(pts, line);
  std::vector<Point> kept;
  for (const Point& p : pts)
    if (std::abs(p.v - line.at(p.t)) <= 3 * line.noise) kept.push_back(p);
  if (kept.size() >= 5 && kept.size() < pts.size()) {
    line = least_squares(kept);
    line.noise = scatter(pts, line);
  }
  return line;
}

std::optional<TrendLine> DepthTrend::level(double slope) const {
  if (samples_.size() < 3) return std::nullopt;
  std::vector<double> ts, vs;
  for (const Sample& s : samples_) ts.push_back(s.t);
  const double tm = median(ts);
  for (const Sample& s : samples_) vs.push_back(s.v - slope * (s.t - tm));
  return TrendLine{median(std::move(vs)), slope, tm, NAN};
}

double DepthTrend::recent() const {
  std::vector<double> vs;
  for (auto it = samples_.rbegin(); it != samples_.rend() && vs.size() < 3; ++it)
    vs.push_back(it->v);
  return median(std::move(vs));
}

}  // namespace projtrack
