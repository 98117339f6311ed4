// Pixel-filling: flood the object from the inner point up to the edges.
#pragma once

#include <vector>

#include "core/scratch_mask.hpp"
#include "projtrack/estimator.hpp"

namespace projtrack {

// 4-connected (8-connected fills walk through Canny's 8-connected lines), scanline by scanline.
// Exact on a closed contour: centroid = mean of the filled pixels, area = their count. One
// missing edge pixel lets it flood the background.
class PixelFilling final : public Estimator {
 public:
  bool took_in(Point2i p) const override { return filled_.at(p); }
  std::uint64_t add_fill_to(ScratchMask& into, Rect& box) const override;

 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  // The last fill is kept until the next one clears it (for took_in): all zero out of `kept_`.
  ScratchMask filled_;
  Rect kept_;
  // Run seeds to scan, taken first in, first out: a fill the area limit cuts short has then taken
  // in what lies nearest its start, not one long streak, so the acquisition's later seeds near
  // it are known to be in the same region (took_in) and are not filled again.
  std::vector<Point2i> pending_;
};

}  // namespace projtrack
