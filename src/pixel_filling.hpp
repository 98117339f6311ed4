// Pixel-filling: flood the object from the inner point up to the edges.
#pragma once

#include <vector>

#include "estimator.hpp"
#include "scratch_mask.hpp"

namespace projtrack {

// 4-connected (8-connected fills walk through Canny's 8-connected lines), scanline by scanline.
// Exact on a closed contour: centroid = mean of the filled pixels, area = their count. One
// missing edge pixel lets it flood the background.
class PixelFilling final : public Estimator {
 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  ScratchMask filled_;
  std::vector<Point2i> pending_;  // run seeds still to scan
};

}  // namespace projtrack
