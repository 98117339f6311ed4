// A set of frame pixels sampled every `step` px, for the silhouettes of several objects met on one
// frame (models at their own scales): mask(y, x) != 0 holds frame pixel
// (origin.x + x·step .. + step, origin.y + y·step .. + step).
#pragma once

#include <opencv2/core.hpp>

namespace projtrack {

struct FramePixels {
  cv::Mat mask;  // CV_8U
  cv::Point origin;
  int step = 1;
  int count = 0;  // non-zero samples

  bool empty() const { return count == 0; }
  bool contains(int x, int y) const {
    if (mask.empty() || x < origin.x || y < origin.y) return false;
    const int mx = (x - origin.x) / step, my = (y - origin.y) / step;
    return mx < mask.cols && my < mask.rows && mask.at<std::uint8_t>(my, mx) != 0;
  }
  // The frame area the set covers, px².
  double area() const { return static_cast<double>(count) * step * step; }
};

}  // namespace projtrack
