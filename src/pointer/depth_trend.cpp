#include "pointer/depth_trend.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace projtrack {

double median(std::vector<double>& v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2) return *mid;
  return (*mid + *std::max_element(v.begin(), mid)) / 2;
}

TrendLine least_squares(const std::vector<TimedValue>& pts) {
  double tm = 0, vm = 0;
  for (const TimedValue& p : pts) tm += p.t, vm += p.v;
  tm /= static_cast<double>(pts.size());
  vm /= static_cast<double>(pts.size());
  double stt = 0, stv = 0;
  for (const TimedValue& p : pts) stt += (p.t - tm) * (p.t - tm), stv += (p.t - tm) * (p.v - vm);
  return {vm, stt > 0 ? stv / stt : 0.0, tm, NAN};
}

TrendLine median_line(const std::vector<TimedValue>& pts, double slope,
                      std::vector<double>& scratch) {
  scratch.clear();
  for (const TimedValue& p : pts) scratch.push_back(p.t);
  const double tm = median(scratch);
  scratch.clear();
  for (const TimedValue& p : pts) scratch.push_back(p.v - slope * (p.t - tm));
  return TrendLine{median(scratch), slope, tm, NAN};
}

void DepthTrend::add(double t, double v, double window, double guard) {
  samples_.push_back({t, v});
  // A few dozen samples: erasing from the front moves them, and never allocates.
  auto old = samples_.begin();
  while (old != samples_.end() && old->t < t - window - guard) ++old;
  samples_.erase(samples_.begin(), old);
}

double DepthTrend::scatter(const std::vector<TimedValue>& pts, const TrendLine& line) {
  scratch_.clear();
  for (const TimedValue& p : pts) scratch_.push_back(std::abs(p.v - line.at(p.t)));
  return 1.4826 * median(scratch_);
}

std::optional<TrendLine> DepthTrend::fit(double t, double guard, double settle) {
  pts_.clear();
  for (const TimedValue& s : samples_)
    if (s.t <= t - guard) pts_.push_back(s);
  if (pts_.size() < 5 || pts_.back().t - pts_.front().t < settle) return std::nullopt;
  TrendLine line = least_squares(pts_);
  line.noise = scatter(pts_, line);
  kept_.clear();
  for (const TimedValue& p : pts_)
    if (std::abs(p.v - line.at(p.t)) <= 3 * line.noise) kept_.push_back(p);
  if (kept_.size() >= 5 && kept_.size() < pts_.size()) {
    line = least_squares(kept_);
    line.noise = scatter(pts_, line);
  }
  return line;
}

std::optional<TrendLine> DepthTrend::level(double slope) {
  if (samples_.size() < 3) return std::nullopt;
  return median_line(samples_, slope, scratch_);
}

double DepthTrend::recent() {
  scratch_.clear();
  for (auto it = samples_.rbegin(); it != samples_.rend() && scratch_.size() < 3; ++it)
    scratch_.push_back(it->v);
  return median(scratch_);
}

}  // namespace projtrack
