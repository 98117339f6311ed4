// The paper's figures, which our copy lacks: each method drawn on the sphere and on the hand.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "projtrack/features.hpp"
#include "projtrack/method.hpp"
#include "projtrack/trace.hpp"

namespace projtrack::bench {

// Draws what the estimator did over the dimmed frame and its edges (white): filled pixels
// (cyan), grid lines (magenta), selected blocks (blue), rays (green) and hits (yellow), the
// bounding box (red), the estimated centroid (red cross), the true centroid (white cross) and
// the starting inner point (yellow square). Iterative methods get one panel for the first
// iteration and one for the last, as in the paper. Crops around `focus` and enlarges 2×.
cv::Mat draw_figure(const cv::Mat& gray, const cv::Mat& edges, Method method, const Features& f,
                    const Trace& trace, Point2d true_centroid, const cv::Rect& focus);

}  // namespace projtrack::bench
