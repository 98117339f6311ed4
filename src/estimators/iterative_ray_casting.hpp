// Iterative n-ray-casting: cast, move the inner point toward the centroid, repeat.
#pragma once

#include <vector>

#include "projtrack/estimator.hpp"

namespace projtrack {

class IterativeRayCasting final : public Estimator {
 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  std::vector<RayHit> hits_;
};

}  // namespace projtrack
