#include "motion/dense_flow.hpp"

namespace projtrack {

bool DenseFlow::compute(const cv::Mat& gray) {
  const bool comparable = !last_.empty() && last_.size() == gray.size();
  if (comparable) {
    // The ultrafast preset: 0.3-1.4 ms a frame at a quarter to a half of 854×480, and the motion
    // of a whole object needs no finer field (docs/tracker.md, "The flow model").
    if (!dis_) dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
    dis_->calc(gray, last_, flow_);
  }
  gray.copyTo(last_);
  return comparable;
}

void DenseFlow::reset() {
  last_.release();
  flow_.release();
}

}  // namespace projtrack
