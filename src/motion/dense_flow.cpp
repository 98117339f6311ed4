#include "motion/dense_flow.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace projtrack {

bool DenseFlow::compute(const cv::Mat& gray) {
  // DIS reads the frame at half size from that size's finest level but one: the ultrafast
  // preset's finest level of the whole frame is a quarter of it, so the field is measured at the
  // same level from a quarter of the pixels to build pyramids from (0.3 ms less a frame at
  // 427×240; davis-dev's J within a point either way). A frame too small to halve is read whole.
  const bool halve = std::min(gray.cols, gray.rows) >= 2 * kLeastSide;
  if (halve)
    cv::resize(gray, half_, {(gray.cols + 1) / 2, (gray.rows + 1) / 2}, 0, 0, cv::INTER_AREA);
  const cv::Mat& read = halve ? half_ : gray;
  const bool comparable =
      !last_.empty() && last_size_ == gray.size() && std::min(gray.cols, gray.rows) >= kLeastSide;
  if (!comparable) dis_.release();  // a new size: a new DIS (reset())
  bool computed = false;
  if (comparable) {
    // The ultrafast preset: 0.3-1.4 ms a frame at a quarter to a half of 854×480, and the motion
    // of a whole object needs no finer field (docs/tracker.md, "The flow model").
    if (!dis_) {
      dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
      if (halve) dis_->setFinestScale(dis_->getFinestScale() - 1);
    }
    try {
      dis_->calc(read, last_, read_flow_);
      if (halve) {
        // To the frame's size, as DIS itself brings its finest level's field up.
        cv::resize(read_flow_, flow_, gray.size(), 0, 0, cv::INTER_LINEAR);
        cv::multiply(flow_,
                     cv::Scalar(static_cast<double>(gray.cols) / read.cols,
                                static_cast<double>(gray.rows) / read.rows),
                     flow_);
      } else {
        cv::swap(flow_, read_flow_);
      }
      computed = true;
    } catch (const cv::Exception&) {
      dis_.release();  // no flow on this frame: the caller says the object was not followed
    }
  }
  read.copyTo(last_);
  last_size_ = gray.size();
  return computed;
}

void DenseFlow::reset() {
  // A new DIS too: OpenCV 4.6's keeps buffers of the sizes it has seen, and one reused on frames
  // of another size after a few of a smaller one crashed in its parallel loop (tests/gst's flow
  // model through a new resolution and a reset).
  dis_.release();
  last_.release();
  flow_.release();
  last_size_ = {};
}

}  // namespace projtrack
