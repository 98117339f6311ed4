#include "motion/dense_flow.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

// Each vector of a two-channel field scaled by (sx, sy): cv::multiply by a Scalar took 0.09 ms at
// 427×240, this loop 0.03.
void scale_components(float sx, float sy, cv::Mat& field) {
  for (int y = 0; y < field.rows; ++y) {
    float* f = field.ptr<float>(y);
    for (int x = 0; x < 2 * field.cols; x += 2) {
      f[x] *= sx;
      f[x + 1] *= sy;
    }
  }
}

}  // namespace

bool DenseFlow::compute(const cv::Mat& gray, int level) {
  level = std::clamp(level, 0, kPresetLevel);
  // Above level 0 DIS reads the frame halved, from the half's level below: the field is measured
  // at the same level from a quarter of the pixels to build pyramids from (0.3 ms less a frame at
  // 427×240; davis-dev's J within a point either way). A frame too small to halve is read whole.
  const bool halve = level >= 1 && std::min(gray.cols, gray.rows) >= 2 * kLeastSide;
  const bool comparable =
      !last_.empty() && last_.size() == gray.size() && std::min(gray.cols, gray.rows) >= kLeastSide;
  // A new size or level: a new DIS (reset()).
  if (!comparable || level != level_) dis_.release();
  if (halve)
    cv::resize(gray, half_, {(gray.cols + 1) / 2, (gray.rows + 1) / 2}, 0, 0, cv::INTER_AREA);
  bool computed = false;
  if (comparable) {
    // The ultrafast preset's patches and iterations, down to the level asked: 0.3-1.4 ms a frame
    // at its own level, a quarter to a half of 854×480; a finer level is asked for a small object
    // only (docs/tracker.md, "The flow model").
    if (!dis_) {
      dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
      dis_->setFinestScale(halve ? level - 1 : level);
    }
    if (halve && !last_halved_) cv::resize(last_, last_half_, half_.size(), 0, 0, cv::INTER_AREA);
    const cv::Mat& read = halve ? half_ : gray;
    try {
      dis_->calc(read, halve ? last_half_ : last_, read_flow_);
      if (halve) {
        // To the frame's size, as DIS itself brings its finest level's field up.
        cv::resize(read_flow_, flow_, gray.size(), 0, 0, cv::INTER_LINEAR);
        scale_components(static_cast<float>(gray.cols) / read.cols,
                         static_cast<float>(gray.rows) / read.rows, flow_);
      } else {
        cv::swap(flow_, read_flow_);
      }
      computed = true;
    } catch (const cv::Exception&) {
      dis_.release();  // no flow on this frame: the caller says the object was not followed
    }
  }
  level_ = level;
  gray.copyTo(last_);
  last_halved_ = halve;
  if (halve) cv::swap(last_half_, half_);
  return computed;
}

void DenseFlow::reset() {
  // A new DIS too: OpenCV 4.6's keeps buffers of the sizes it has seen, and one reused on frames
  // of another size after a few of a smaller one crashed in its parallel loop (tests/gst's flow
  // model through a new resolution and a reset).
  dis_.release();
  last_.release();
  last_halved_ = false;
  flow_.release();
}

}  // namespace projtrack
