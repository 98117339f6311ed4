// The stopping rule of the iterative methods.
#pragma once

#include "geometry.hpp"

namespace projtrack {

// "Until the centroid and inner point adjustment is negligible": both moved less than
// `threshold` px; or the inner point did not move at all, a fixed point that the next iteration
// would only repeat.
inline bool converged(Point2i p_before, Point2i p_after, Point2d c_before, Point2d c_after,
                      double threshold) {
  const double dp = distance(p_before, p_after);
  if (dp == 0) return true;
  return dp < threshold && distance(c_before, c_after) < threshold;
}

}  // namespace projtrack
