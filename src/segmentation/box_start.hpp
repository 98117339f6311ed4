// The object within a user's box, for the flow model, at a cost set by the box's cells and not
// by the frame or the picture: the box read at about `box_pixels` cells and its surroundings
// (the box grown by half its sides) at as many, two rounds of colour models and labels
// (start_cut), the last by an exact cut, and every piece of the object of at least a tenth of
// the largest.
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/color_view.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/work_budget.hpp"
#include "segmentation/start_cut.hpp"
#include "segmentation/start_outcome.hpp"

namespace projtrack {

// The object in `box` (frame px) of `frame`, into `inside` (CV_8U of `out_size`, the frame's
// working size: 255 on the object; meaningful on a Cut only), paid from `budget`.
StartOutcome object_in_box(const ColorView& frame, const Rect& box, double box_pixels,
                           cv::Size out_size, CutWorkspace& ws, WorkBudget& budget,
                           cv::Mat& inside);

}  // namespace projtrack
