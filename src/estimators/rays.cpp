#include "projtrack/rays.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

void RayFan::set_count(int n) {
  if (n == count()) return;
  dirs_.resize(n);
  const double pi = std::acos(-1.0);
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * pi * k / n;
    const double c = std::cos(a), s = std::sin(a);
    const double major = std::max(std::abs(c), std::abs(s));
    const double ux = c / major, uy = s / major;  // one step: 1 px along the major axis
    dirs_[k] = {std::llround(ux * 65536.0), std::llround(uy * 65536.0), 0.5 * ux, 0.5 * uy};
  }
}

Point2d cast_fan(const ImageView& edges, Point2i origin, const RayFan& fan,
                 std::vector<RayHit>& hits, Work& work) {
  double sx = 0, sy = 0;
  for (int k = 0; k < fan.count(); ++k) {
    if (work.must_stop()) break;
    const RayHit h = fan.cast(edges, origin, k);
    work.steps(h.length + 1);
    work.cost += kCostPerRay;
    ++work.rays;
    work.reach.add(h.last_free.x, h.last_free.y);
    sx += h.hit.x;
    sy += h.hit.y;
    hits.push_back(h);
  }
  return {sx / fan.count(), sy / fan.count()};
}

double fan_area(const RayHit* hits, int count, Point2i origin) {
  double twice = 0;
  for (int i = 0; i < count; ++i) {
    const Point2d& a = hits[i].hit;
    const Point2d& b = hits[(i + 1) % count].hit;
    twice += (a.x - origin.x) * (b.y - origin.y) - (b.x - origin.x) * (a.y - origin.y);
  }
  return 0.5 * std::abs(twice);
}

}  // namespace projtrack
