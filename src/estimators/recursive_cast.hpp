// The n^y cast shared by recursive and rasterized ray-casting.
#pragma once

#include <vector>

#include "projtrack/rays.hpp"
#include "projtrack/trace.hpp"

namespace projtrack {

// Casts n rays from the origin, then n from each hit (from its last free pixel), y levels deep:
// n^y rays in the last level. Keeps the last level's fans: origins() and hits(), fan k being
// hits()[k*n .. k*n+n). Stops between rays when work.must_stop(): then the fans kept are
// incomplete, and the mean returned is meaningless.
class RecursiveCast {
 public:
  // Returns the mean of the last level's hit points. visit(x, y) sees every pixel every ray
  // runs through, at every level.
  template <class Visit>
  Point2d cast(const ImageView& edges, Point2i origin, const RayFan& fan, int levels, Work& work,
               Trace* trace, int iteration, Visit&& visit);

  const std::vector<Point2i>& origins() const { return origins_; }
  const std::vector<RayHit>& hits() const { return hits_; }

 private:
  std::vector<Point2i> origins_, next_;
  std::vector<RayHit> hits_;
};

template <class Visit>
Point2d RecursiveCast::cast(const ImageView& edges, Point2i origin, const RayFan& fan, int levels,
                            Work& work, Trace* trace, int iteration, Visit&& visit) {
  const int n = fan.count();
  origins_.assign(1, origin);
  for (int level = 1;; ++level) {
    hits_.clear();
    for (const Point2i& o : origins_) {
      for (int k = 0; k < n; ++k) {
        if (work.must_stop()) return {};  // the caller drops the result
        const RayHit h = fan.cast(edges, o, k, visit);
        work.steps(h.length + 1);
        work.cost += kCostPerRay;
        ++work.rays;
        work.reach.add(h.last_free.x, h.last_free.y);
        hits_.push_back(h);
        if (trace) trace->add_ray({to_double(o), h.hit, iteration, level});
      }
    }
    if (level == levels) break;
    next_.clear();
    for (const RayHit& h : hits_) next_.push_back(h.last_free);
    origins_.swap(next_);
  }
  double sx = 0, sy = 0;
  for (const RayHit& h : hits_) {
    sx += h.hit.x;
    sy += h.hit.y;
  }
  return {sx / hits_.size(), sy / hits_.size()};
}

}  // namespace projtrack
