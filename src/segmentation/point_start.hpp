// The object at a user's point, for the flow model: GrabCut around the point at a few sizes (the
// object's size is unknown), and the candidate the others agree with most: the object is what the
// cuts at most sizes take; a cut too small takes a patch of it, one too large takes background
// too, each differently.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segmentation/work_images.hpp"

namespace projtrack {

// GrabCut's object around work pixel `p`, in a square of half-side `half` (work px) with a disc
// a tenth of `half` around the point certain and the ellipse half the square's size probable: one
// candidate per half-side in `halves`, each CV_8U at the work size, the piece holding `p` only;
// empty where GrabCut could not run or collapsed (kept under 2 % of its square, or under twice
// its certain disc: hardly more than what it was told).
std::vector<cv::Mat> objects_at_point(const WorkImages& img, cv::Point p,
                                      const std::vector<int>& halves);

// The index of the candidate (CV_8U masks of one size; empty ones take no part) whose summed
// intersection over union with the others is the highest, the later on a tie; -1 when all are
// empty.
int most_agreed(const std::vector<cv::Mat>& candidates);

}  // namespace projtrack
