// How the whole picture moved between two frames: dense optical flow at the working scale
// (OpenCV's DIS, the library made for it), computed once per frame for every user of it.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

namespace projtrack {

class DenseFlow {
 public:
  // DIS's ultrafast preset measures the field at a quarter of the frame's size: pyramid level 2.
  static constexpr int kPresetLevel = 2;
  // The flow from `gray` (this frame, work scale, CV_8U) back to the last frame given: for each
  // pixel of this frame, where it was on the last one (CV_32FC2, work pixels), measured at
  // pyramid level `level` of `gray` (0: `gray` itself, 1: half its size, 2: a quarter; clamped
  // to those) and brought up to its size. False, with no flow, on the first frame, after a
  // change of size (nothing to compare with) and on a frame whose smaller side is under
  // kLeastSide (DIS refuses it).
  static constexpr int kLeastSide = 16;
  bool compute(const cv::Mat& gray, int level = kPresetLevel);
  const cv::Mat& backward() const { return flow_; }
  // Forgets the last frame: the next compute() starts afresh.
  void reset();

 private:
  cv::Ptr<cv::DISOpticalFlow> dis_;
  int level_ = kPresetLevel;  // the level dis_ measures at
  cv::Mat last_;              // the last frame
  cv::Mat last_half_;         // halved, when it was (last_halved_)
  bool last_halved_ = false;
  cv::Mat flow_;              // at the frame's size
  cv::Mat half_, read_flow_;  // buffers: the frame halved, the field DIS gave
};

}  // namespace projtrack
