// The object within a user's box, for the flow model: OpenCV's GrabCut (colour mixtures inside
// and around the box, a contrast-aware cut), the library made for exactly this, at the working
// scale.
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/geometry.hpp"
#include "segmentation/work_images.hpp"

namespace projtrack {

// `inside` (CV_8U at the work size): 255 on the object GrabCut finds in `work_box` (work pixels).
// A box GrabCut cannot split (too small, or one colour) gives the ellipse inscribed in it, which
// the caller is told of by the return value: false.
bool object_in_box(const WorkImages& img, const Rect& work_box, cv::Mat& inside);

}  // namespace projtrack
