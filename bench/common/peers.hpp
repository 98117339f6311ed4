// The stock-OpenCV way of doing the estimators' job, as peers in the benchmark.
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/features.hpp"

namespace projtrack::bench {

// cv::floodFill (4-connected) of a copy of the edge map from the seed; centroid from moments.
class OpenCvFloodFill {
 public:
  Features estimate(const cv::Mat& edges, Point2i seed);

 private:
  cv::Mat work_;
};

// cv::connectedComponentsWithStats (4-connected) of the non-edge pixels; the seed's component.
class OpenCvComponents {
 public:
  Features estimate(const cv::Mat& edges, Point2i seed);

 private:
  cv::Mat free_, labels_, stats_, centroids_;
};

}  // namespace projtrack::bench
