// OpenCV's GrabCut with the same answer for the same picture: it seeds its colour mixtures with
// k-means from the calling thread's global RNG, so a start otherwise depended on whatever drew
// from that RNG before (davis-dev from the box: libby's J 30.3 alone, 34.8 after nine other
// sequences in the same process).
#pragma once

#include <opencv2/core.hpp>

namespace projtrack {

// cv::grabCut(bgr, labels, box, ..., rounds, mode) from a fixed RNG state (the caller's state is
// put back afterwards); false when GrabCut cannot run (one colour in and around the region: no
// mixture to learn). `labels` as cv::grabCut's mask.
bool repeatable_grab_cut(const cv::Mat& bgr, cv::Mat& labels, const cv::Rect& box, int rounds,
                         int mode);

}  // namespace projtrack
