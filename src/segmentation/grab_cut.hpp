// OpenCV's GrabCut as the flow model's starts run it: the same frame and seed always give the same
// cut. Its colour mixtures are seeded by k-means from OpenCV's thread-wide random generator, whose
// state depends on whatever ran before in the thread: the same box on the same frame gave J0 from
// 60 to 69 on davis-dev's libby from one run of the benchmark to the next.
#pragma once

#include <opencv2/core.hpp>

namespace projtrack {

// cv::grabCut on `bgr` for `rounds` iterations with a fixed seed (the thread's generator is
// restored after): from `rect` when it is not empty (`labels` is then written), else from the
// labels in `labels` (GC_BGD, GC_FGD, GC_PR_BGD, GC_PR_FGD). False when GrabCut cannot run (one
// colour in the image: no mixture to learn).
bool grab_cut(const cv::Mat& bgr, cv::Mat& labels, const cv::Rect& rect, int rounds);

}  // namespace projtrack
