// A rectangle of the frame read at about a given number of pixels, for the starts: what a start
// reads costs that number, not the frame's size or the rectangle's.
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/color_view.hpp"

namespace projtrack {

struct Patch {
  cv::Mat bgr;            // CV_8UC3, full range (as the work images)
  cv::Rect rect;          // frame px
  double kx = 1, ky = 1;  // patch px per frame px
};

// The size `rect` is read at for about `pixels` pixels: never finer than the frame, at least 1×1.
cv::Size patch_size(const cv::Rect& rect, double pixels);
// `rect` (within the frame) of `frame` at patch_size(rect, pixels): each patch pixel the mean of
// 2 × 2 samples spread over the frame pixels it covers (all of them when it covers up to 2 × 2).
void read_patch(const ColorView& frame, const cv::Rect& rect, double pixels, Patch& out);

}  // namespace projtrack
