// The object within a user's box, for the flow model: OpenCV's GrabCut (colour mixtures inside
// and around the box, a contrast-aware cut), the library made for exactly this, at a resolution
// relative to the box.
#pragma once

#include <array>
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
// frame — and the object where the cuts agree (cuts_vote). GrabCut's result turns on
// the balance of its colour terms (per pixel) and its boundary terms (per pixel of outline),
// which the box's size in pixels sets: read at the working scale, a small object was cut at a
// coarse grain and a large one at a fine grain, and one resolution alone is a coin toss on
// some boxes (davis-dev). Cut when at least one of the three was a cut.
BoxStart object_in_box(const cv::Mat& frame, const Rect& box, double box_pixels, cv::Size work_size,
                       cv::Mat& inside);

// The vote of `votes` (CV_8U masks of one size, 255 on the object) into `inside`: where at least
// half of those whose `how` is Cut set it — a collapsed cut's ellipse says nothing of where the
// object is — or, when none is a cut, where at least two of them do. Empty when they agree
// nowhere.
void cuts_vote(const std::array<cv::Mat, 3>& votes, const std::array<BoxStart, 3>& how,
               cv::Mat& inside);

}  // namespace projtrack
