// The object at a user's point, for the flow model: GrabCut around the point at a few sizes (the
// object's size is unknown), each candidate judged by how far its colours stand apart from its
// ring's; the caller adds its own candidates to the choice.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segmentation/work_images.hpp"

namespace projtrack {

// How far the colours inside `inside` (CV_8U) stand apart from those of a ring around it a
// quarter of √area wide (colour_separation); -1 for a candidate too small to judge (under 16 work
// px) or with no ring.
double separation_from_ring(const cv::Mat& bgr, const cv::Mat& inside);

// GrabCut's object around work pixel `p`, in a square of half-side `half` (work px) with the
// point's close neighbourhood certain and the ellipse half the square's size probable: one
// candidate per half-side in `halves`, each CV_8U at the work size (empty where GrabCut could not
// run), the piece holding `p` only.
std::vector<cv::Mat> objects_at_point(const WorkImages& img, cv::Point p,
                                      const std::vector<int>& halves);

}  // namespace projtrack
