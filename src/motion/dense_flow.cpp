#include "motion/dense_flow.hpp"

#include <algorithm>

namespace projtrack {

bool DenseFlow::compute(const cv::Mat& gray) {
  const bool comparable =
      !last_.empty() && last_.size() == gray.size() && std::min(gray.cols, gray.rows) >= kLeastSide;
  if (!comparable) dis_.release();  // a new size: a new DIS (reset())
  bool computed = false;
  if (comparable) {
    // The ultrafast preset: 0.3-1.4 ms a frame at a quarter to a half of 854×480, and the motion
    // of a whole object needs no finer field (docs/tracker.md, "The flow model").
    if (!dis_) dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
    try {
      dis_->calc(gray, last_, flow_);
      computed = true;
    } catch (const cv::Exception&) {
      dis_.release();  // no flow on this frame: the caller says the object was not followed
    }
  }
  gray.copyTo(last_);
  return computed;
}

void DenseFlow::reset() {
  // A new DIS too: OpenCV 4.6's keeps buffers of the sizes it has seen, and one reused on frames
  // of another size after a few of a smaller one crashed in its parallel loop (tests/gst's flow
  // model through a new resolution and a reset).
  dis_.release();
  last_.release();
  flow_.release();
}

}  // namespace projtrack
