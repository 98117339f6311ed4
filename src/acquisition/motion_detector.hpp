// Frame differencing: where the picture changed since the previous frame. The original system
// picked the object to track this way: once enough of the frame moves, the moving region is it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "projtrack/geometry.hpp"
#include "projtrack/image_view.hpp"
#include "projtrack/motion_params.hpp"

namespace projtrack {

class MotionDetector {
 public:
  using Params = MotionParams;
  struct Motion {
    double fraction = 0;          // of the sampled pixels that changed
    Point2d centroid;             // of the changed samples (valid when fraction > 0)
    std::vector<Point2i> points;  // the changed samples, in frame coordinates, row by row
    int step = 1;                 // the samples' spacing, px (Params::step)
  };

  // Compares `gray` with the previous frame and keeps it for the next call. Returns false (and
  // no motion) on the first frame, after reset() or when the frame size changed.
  bool update(const ImageView& gray, const Params& p, Motion& out);
  void reset() { width_ = height_ = spread_ = 0; }
  // How many grey levels the last frame's samples span, from the 2nd to the 98th percentile (0
  // before the first frame): a dim scene spans fewer, and its changes are as much smaller.
  int spread() const { return spread_; }

 private:
  std::vector<std::uint8_t> previous_;  // the sampled previous frame
  int width_ = 0, height_ = 0, step_ = 0, spread_ = 0;
  std::array<std::uint32_t, 256> histogram_{};
  std::vector<int> changed_;  // one row's changed columns (update)
};

}  // namespace projtrack
