// Canny's edge detector (3×3 Sobel, L1 gradient, hysteresis), the same edges as
// cv::Canny(src, dst, low, high, 3, false), on buffers kept between calls: after the first call
// for a size, no allocation. OpenCV's allocates its buffers on every call, and on the small
// regions a tracker asks for its setup is a large share of the cost (docs/performance.md).
#pragma once

#include <cstdint>
#include <vector>

#include "image_view.hpp"

namespace projtrack {

class CannyDetector {
 public:
  // Edges of `src` (replicated at its border) into `dst` (src's size, rows `dst_stride` apart):
  // 255 on an edge, 0 elsewhere. Thresholds as cv::Canny's: swapped if low > high, floored.
  void detect(const ImageView& src, double low, double high, std::uint8_t* dst,
              std::ptrdiff_t dst_stride);

 private:
  std::vector<std::int16_t> dx_, dy_, mag_;  // mag_ has a zero border of one pixel
  std::vector<std::uint8_t> map_;            // 0 maybe an edge, 1 not, 2 an edge; border 1
  std::vector<std::int32_t> stack_;          // map_ offsets of edges still to extend
};

}  // namespace projtrack
