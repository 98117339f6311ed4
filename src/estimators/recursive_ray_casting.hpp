// Iterative n^y-ray-casting: re-cast from every hit point, y levels deep, and iterate.
#pragma once

#include <vector>

#include "core/scratch_mask.hpp"
#include "estimators/recursive_cast.hpp"
#include "projtrack/estimator.hpp"

namespace projtrack {

// Centroid: the mean of the last level's n^y hits. Area: the pixels covered by the union of the
// last level's fans (each fan is the star polygon through one origin's n hits), i.e. the area the
// rays sweep, computed once after the last iteration.
class RecursiveRayCasting final : public Estimator {
 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  RecursiveCast cast_;
  ScratchMask covered_;
};

}  // namespace projtrack
