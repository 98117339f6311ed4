// The arm that holds an object, cut off the object's first silhouette from a click. An object
// held in a hand is in view; the arm that holds it enters from the frame's border, and a cut from
// a click that reaches the border has taken it in (a cup's hand and forearm: as sharp against
// the wall as the cup, and joined to it). Its colours are read where the cut meets the border,
// the object's around the click; the cut's pixels the arm's colours explain better are dropped,
// and the part left that holds the click is the object — when it is a fair part of the cut and
// clear of the border itself (else the cut stands: an object that fills the view, or reaches the
// border itself).
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/work_budget.hpp"

namespace projtrack {

// `mask` (CV_8U, non-zero on the object) of `bgr` (CV_8UC3, its size) without the arm; `click`
// in its pixels. True when trimmed. Its work (two histograms and a pass over the mask's box) is
// paid from `budget`; unchanged when it cannot pay.
bool trim_arm(const cv::Mat& bgr, cv::Point click, WorkBudget& budget, cv::Mat& mask);

}  // namespace projtrack
