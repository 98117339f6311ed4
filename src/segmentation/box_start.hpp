// The object within a user's box, for the flow model: OpenCV's GrabCut (colour mixtures inside
// and around the box, a contrast-aware cut), the library made for exactly this, at the working
// scale.
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

// `inside` (CV_8U at the work size): 255 on the object found in `work_box` (work pixels), and how.
BoxStart object_in_box(const WorkImages& img, const Rect& work_box, cv::Mat& inside);

}  // namespace projtrack
