// Iterative n^y-ray-casting with m-rasterization: every m×m block a ray runs through is selected,
// and selected blocks are kept across iterations.
#pragma once

#include <cstdint>
#include <vector>

#include "estimators/recursive_cast.hpp"
#include "projtrack/estimator.hpp"

namespace projtrack {

// Blocks are anchored at the frame's origin (so they line up across iterations) and clipped to
// the frame. Centroid: the centroid of the union of selected blocks (each block weighted by its
// clipped area: the paper's "average of the block positions" for whole blocks). Area: the sum of
// the selected blocks' areas.
class RasterizedRayCasting final : public Estimator {
 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  RecursiveCast cast_;
  std::vector<std::uint8_t> selected_;  // one byte per block of the frame
};

}  // namespace projtrack
