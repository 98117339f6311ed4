// How the whole picture moved between two frames: dense optical flow at the working scale
// (OpenCV's DIS, the library made for it), computed once per frame for every user of it.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

namespace projtrack {

class DenseFlow {
 public:
  // The flow from `gray` (this frame, work scale, CV_8U) back to the last frame given: for each
  // pixel of this frame, where it was on the last one (CV_32FC2, work pixels). False, with no
  // flow, on the first frame, after a change of size (nothing to compare with) and on a frame
  // whose smaller side is under kLeastSide (DIS refuses it).
  static constexpr int kLeastSide = 16;
  bool compute(const cv::Mat& gray);
  const cv::Mat& backward() const { return flow_; }
  // Forgets the last frame: the next compute() starts afresh.
  void reset();

 private:
  cv::Ptr<cv::DISOpticalFlow> dis_;
  cv::Mat last_;              // the last frame as DIS read it (at half size when it was halved)
  cv::Size last_size_;        // the last frame's own size
  cv::Mat flow_;              // at the frame's size
  cv::Mat half_, read_flow_;  // buffers: the frame halved, the field DIS gave
};

}  // namespace projtrack
