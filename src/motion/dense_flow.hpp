// How the picture moved between two frames: dense optical flow at the working scale (OpenCV's
// DIS, the library made for it), computed once per frame, over the whole frame or the part of it
// its user reads.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

namespace projtrack {

class DenseFlow {
 public:
  // DIS's ultrafast preset measures the field at a quarter of the frame's size: pyramid level 2.
  static constexpr int kPresetLevel = 2;
  // The coarsest level a large region is read at (its user's choice: the cost of a frame).
  static constexpr int kMaxLevel = 4;
  // Its patches' side at the level it reads: a patch at the edge of the part measured sees less
  // of the picture than one within.
  static constexpr int kPatchSide = 8;
  // The flow from `gray` (this frame, work scale, CV_8U) back to the last frame given: for each
  // pixel of this frame, where it was on the last one (CV_32FC2, work pixels), measured at
  // pyramid level `level` of `gray` (0: `gray` itself, 1: half its size, 2: a quarter; clamped
  // to 0 .. kMaxLevel) and brought up to its size. False, with no flow, on the first frame, after a
  // change of size (nothing to compare with) and on a frame whose smaller side is under
  // kLeastSide (DIS refuses it).
  // Only the motion within `region` (work px) is measured when it is given: the flow is zero
  // outside it (a region too small for DIS is grown to its least size; an empty one is the whole
  // frame). Only the part `valid` of `gray` holds this frame (empty: all of it; the rest is a
  // past frame's, WorkImages::filled): the motion is measured within what this frame's and the
  // last frame's valid parts share, and false when that is too small for DIS.
  static constexpr int kLeastSide = 16;
  bool compute(const cv::Mat& gray, int level = kPresetLevel, cv::Rect region = cv::Rect(),
               cv::Rect valid = cv::Rect());
  const cv::Mat& backward() const { return flow_; }
  // The part of backward() that was measured: the field is zero outside it.
  const cv::Rect& measured() const { return measured_; }
  // Forgets the last frame: the next compute() starts afresh.
  void reset();
  // The frames are now `size` (another scale of the same picture): the last frame is resampled to
  // it, so that the next compute() measures the motion against it.
  void resample(cv::Size size);

 private:
  // DIS on `region` of the frame read (halved or not), the field brought up into flow_.
  bool measure(const cv::Mat& gray, int level, bool halve, const cv::Rect& region,
               const cv::Rect& both);
  // `part` of `gray` halved (INTER_AREA) into its place in `half`, half `gray`'s size.
  static void halve_into(const cv::Mat& gray, const cv::Rect& part, cv::Mat& half);

  cv::Ptr<cv::DISOpticalFlow> dis_;
  int level_ = kPresetLevel;  // the level dis_ measures at
  cv::Mat last_;              // the last frame
  cv::Rect last_valid_;       // the part of last_ that holds it
  cv::Mat last_half_;         // halved, when it was (last_halved_)
  bool last_halved_ = false;
  cv::Mat flow_;       // at the frame's size
  cv::Rect measured_;  // flow_'s measured part
  cv::Size dis_size_;  // the size of the images dis_ was made for
  // Buffers: the frame halved, the part of this and the last frame DIS reads (continuous), the
  // field DIS gave.
  cv::Mat half_, now_, before_, read_flow_;
};

}  // namespace projtrack
