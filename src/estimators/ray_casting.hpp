// n-ray-casting: the centroid is the mean of n ray hits from the inner point.
#pragma once

#include <vector>

#include "projtrack/estimator.hpp"

namespace projtrack {

// Area: the star polygon through the hits (the paper's "sum of the ray lengths" is not an area).
class RayCasting final : public Estimator {
 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  std::vector<RayHit> hits_;
};

// Shared by the ray methods: the bounding box of a fan, and its record in a trace.
Rect fan_bounds(Point2i origin, const std::vector<RayHit>& hits);
void trace_fan(Trace* trace, Point2i origin, const RayHit* hits, int count, int iteration,
               int level);

}  // namespace projtrack
