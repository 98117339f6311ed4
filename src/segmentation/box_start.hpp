// The object within a user's box, for the flow model: OpenCV's GrabCut (colour mixtures inside
// and around the box, a contrast-aware cut), the library made for exactly this, at a resolution
// relative to the box.
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/geometry.hpp"
#include "segmentation/work_images.hpp"

namespace projtrack {

// How the object in a user's box was found.
enum class BoxStart {
  Cut,      // GrabCut separated it
  Ellipse,  // GrabCut could not run or collapsed (took next to nothing): the inscribed ellipse
};

// `inside` (CV_8U, `bgr`'s size): 255 on the object found in `box` (`bgr`'s pixels), and how.
BoxStart object_in_box(const cv::Mat& bgr, const Rect& box, cv::Mat& inside);

// The object in the user's `box` (frame pixels) on `frame` (BGR at full resolution), into
// `inside` (CV_8U of `work_size`, the frame's working size): GrabCut at three
// resolutions of the box — about ½, 1 and 2 × `box_pixels` pixels in it, never finer than the
// frame — and the object where at least two of the three found it. GrabCut's result turns on
// the balance of its colour terms (per pixel) and its boundary terms (per pixel of outline),
// which the box's size in pixels sets: read at the working scale, a small object was cut at a
// coarse grain and a large one at a fine grain, and one resolution alone is a coin toss on
// some boxes (davis-dev). Cut when at least two of the three were cuts.
BoxStart object_in_box(const cv::Mat& frame, const Rect& box, double box_pixels, cv::Size work_size,
                       cv::Mat& inside);

}  // namespace projtrack
