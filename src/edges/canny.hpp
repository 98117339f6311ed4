// Canny's edge detector (3×3 Sobel, L1 gradient, hysteresis), the same edges as
// cv::Canny(src, dst, low, high, 3, false), on buffers kept between calls: after the first call
// for a size, no allocation. OpenCV's allocates its buffers on every call, and on the small
// regions a tracker asks for its setup is a large share of the cost (docs/performance.md).
#pragma once

#include <cstdint>
#include <vector>

#include "projtrack/image_view.hpp"

namespace projtrack {

class WorkBudget;

class CannyDetector {
 public:
  // Edges of `src` (replicated at its border): a view of src's size, 255 on an edge and 0
  // elsewhere, valid until the next call. Thresholds as cv::Canny's: swapped if low > high,
  // floored. An invalid `src` gives an empty view. With a budget (work_budget.hpp) the work is
  // spent from it, and checked every few rows: once it runs out (or its stop flag is set), the
  // rows not reached and the weak candidates are left "not an edge" (budget->ran_out() or
  // interrupted() say so): the view is then incomplete.
  ImageView detect(const ImageView& src, double low, double high, WorkBudget* budget = nullptr);

 private:
  std::vector<std::int16_t> dx_, dy_, mag_;  // three rows each, a border pixel each side
  std::vector<std::uint8_t> map_;            // the edges, with a border of "not an edge"
  std::vector<std::int32_t> stack_;          // map_ offsets of edges still to extend
  std::vector<std::int32_t> maybes_;         // map_ offsets of weak candidates
};

}  // namespace projtrack
