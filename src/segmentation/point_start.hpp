// The object under a user's click, for the flow model, at a fixed cost: the object's size is
// unknown, so each of 9 squares around the click (half-sides from 2 % to 100 % of the frame's
// smaller side, geometric: a thrown ball to a body) is a hypothesis "the object lies within it",
// with the object expected in the disc of half its half-side and certain around the click. Each
// is cut coarsely (400 cells, mean field only) and scored by its cut's outline: sharp (its mean
// contrast) and not the square's edge (a square too small cuts across the object there; one too
// large takes in a hand or a wall, whose outline is weaker). The 2 best are cut again finely
// (4000 cells, the exact cut) and scored again: the best wins. At the coarse grain an outline is
// a few noisy cells (davis-dev from the deepest point: choosing on the coarse cuts alone, J
// 0.39-0.43; on the two best's fine cuts, 0.52).
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/color_view.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/work_budget.hpp"
#include "segmentation/start_cut.hpp"
#include "segmentation/start_outcome.hpp"

namespace projtrack {

// The object under `point` (frame px) of `frame`, into `inside` (CV_8U of `out_size`, the frame's
// working size: 255 on the object; meaningful on a Cut only), paid from `budget`.
StartOutcome object_at_point(const ColorView& frame, Point2i point, cv::Size out_size,
                             CutWorkspace& ws, WorkBudget& budget, cv::Mat& inside);

}  // namespace projtrack
