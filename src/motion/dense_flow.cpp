#include "motion/dense_flow.hpp"

#include <algorithm>
#include <cmath>
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

// The part of an image of `size` that holds `region` (frame px, `scale` frame px a pixel of the
// image), at least 2 × kLeastSide a side where the image allows; the whole image for an empty
// region.
cv::Rect part_read(const cv::Rect& region, cv::Size2f scale, cv::Size size) {
  const cv::Rect whole(0, 0, size.width, size.height);
  if (region.empty()) return whole;
  const int x0 = static_cast<int>(std::floor(region.x / scale.width));
  const int y0 = static_cast<int>(std::floor(region.y / scale.height));
  const int x1 = static_cast<int>(std::ceil(region.br().x / scale.width));
  const int y1 = static_cast<int>(std::ceil(region.br().y / scale.height));
  const int least = 2 * DenseFlow::kLeastSide;
  const int gx = std::max(0, least - (x1 - x0) + 1) / 2,
            gy = std::max(0, least - (y1 - y0) + 1) / 2;
  return cv::Rect(cv::Point(x0 - gx, y0 - gy), cv::Point(x1 + gx, y1 + gy)) & whole;
}

// `part` grown to even corners (or the image's edge): its 2×2 blocks are the whole image's.
cv::Rect even_part(const cv::Rect& part, cv::Size size) {
  return cv::Rect(cv::Point(part.x & ~1, part.y & ~1),
                  cv::Point(std::min(part.br().x + (part.br().x & 1), size.width),
                            std::min(part.br().y + (part.br().y & 1), size.height)));
}

}  // namespace

bool DenseFlow::compute(const cv::Mat& gray, int level, cv::Rect region, cv::Rect valid) {
  level = std::clamp(level, 0, kMaxLevel);
  const cv::Rect frame(0, 0, gray.cols, gray.rows);
  valid = valid.empty() ? frame : valid & frame;
  // Above level 0 DIS reads the frame halved, from the half's level below: the field is measured
  // at the same level from a quarter of the pixels to build pyramids from (0.3 ms less a frame at
  // 427×240; davis-dev's J within a point either way). A frame too small to halve is read whole.
  const bool halve = level >= 1 && std::min(gray.cols, gray.rows) >= 2 * kLeastSide;
  const bool comparable =
      !last_.empty() && last_.size() == gray.size() && std::min(gray.cols, gray.rows) >= kLeastSide;
  // A new size or level: a new DIS (reset()).
  if (!comparable || level != level_) dis_.release();
  // Only the part of the frame that holds it is read, and halved.
  if (halve) halve_into(gray, even_part(valid, gray.size()), half_);
  bool computed = false;
  if (comparable) {
    if (halve && !last_halved_) halve_into(last_, even_part(last_valid_, last_.size()), last_half_);
    computed = measure(gray, level, halve, region, valid & last_valid_);
  }
  level_ = level;
  if (last_.size() != gray.size() || last_.type() != gray.type())
    last_.create(gray.size(), gray.type());
  gray(valid).copyTo(last_(valid));
  last_valid_ = valid;
  last_halved_ = halve;
  if (halve) cv::swap(last_half_, half_);
  return computed;
}

void DenseFlow::halve_into(const cv::Mat& gray, const cv::Rect& part, cv::Mat& half) {
  const cv::Size size((gray.cols + 1) / 2, (gray.rows + 1) / 2);
  if (half.size() != size || half.type() != gray.type()) half.create(size, gray.type());
  const cv::Rect to = cv::Rect(cv::Point(part.x / 2, part.y / 2),
                               cv::Point((part.br().x + 1) / 2, (part.br().y + 1) / 2)) &
                      cv::Rect({0, 0}, size);
  if (to.empty() || part.empty()) return;
  cv::Mat into = half(to);
  cv::resize(gray(part), into, to.size(), 0, 0, cv::INTER_AREA);
}

bool DenseFlow::measure(const cv::Mat& gray, int level, bool halve, const cv::Rect& region,
                        const cv::Rect& both) {
  const cv::Mat& read = halve ? half_ : gray;
  const cv::Size2f scale(static_cast<float>(gray.cols) / read.cols,
                         static_cast<float>(gray.rows) / read.rows);
  // Within what this frame and the last hold (`both`, frame px) only.
  const cv::Rect held(cv::Point(static_cast<int>(std::ceil(both.x / scale.width)),
                                static_cast<int>(std::ceil(both.y / scale.height))),
                      cv::Point(static_cast<int>(both.br().x / scale.width),
                                static_cast<int>(both.br().y / scale.height)));
  const cv::Rect part = part_read(region, scale, read.size()) & held;
  if (part.width < kLeastSide || part.height < kLeastSide) return false;
  // DIS asks for continuous images.
  read(part).copyTo(now_);
  (halve ? last_half_ : last_)(part).copyTo(before_);
  // OpenCV 4.6's DIS keeps buffers of the sizes it has seen, and one reused on images of another
  // size after a few of a smaller one crashed in its parallel loop: a new one for a new size.
  if (!dis_ || now_.size() != dis_size_) {
    // The ultrafast preset's patches and iterations, down to the level asked: 0.3-1.4 ms a frame
    // at its own level, a quarter to a half of 854×480 (docs/tracker.md, "The flow model").
    dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
    dis_->setFinestScale(halve ? level - 1 : level);
    dis_size_ = now_.size();
  }
  try {
    dis_->calc(now_, before_, read_flow_);
  } catch (const cv::Exception&) {
    dis_.release();  // no flow on this frame: the caller says the object was not followed
    return false;
  }
  const cv::Rect frame(0, 0, gray.cols, gray.rows);
  if (!halve && part.size() == frame.size()) {
    cv::swap(flow_, read_flow_);
    measured_ = frame;
    return true;
  }
  const cv::Rect to =
      cv::Rect(cv::Point(cvRound(part.x * scale.width), cvRound(part.y * scale.height)),
               cv::Point(cvRound(part.br().x * scale.width), cvRound(part.br().y * scale.height))) &
      frame;
  // Zero outside `to`: only the last region measured holds anything else (a field of 2 floats a
  // pixel is not cleared whole each frame).
  if (flow_.size() != gray.size() || flow_.type() != CV_32FC2) {
    flow_.create(gray.size(), CV_32FC2);
    measured_ = frame;
  }
  if (to != frame) flow_(measured_).setTo(cv::Scalar::all(0));
  measured_ = to;
  // To the frame's scale, as DIS itself brings its finest level's field up.
  cv::Mat into = flow_(to);
  cv::resize(read_flow_, into, to.size(), 0, 0, cv::INTER_LINEAR);
  if (halve) scale_components(scale.width, scale.height, into);
  return true;
}

void DenseFlow::resample(cv::Size size) {
  if (last_.empty() || last_valid_.empty()) {
    reset();
    return;
  }
  const double rx = static_cast<double>(size.width) / last_.cols;
  const double ry = static_cast<double>(size.height) / last_.rows;
  cv::Mat resized;
  cv::resize(last_, resized, size, 0, 0, rx < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  // Only the part that held the last frame still does (shrunk inward: its edge pixels mixed).
  const cv::Rect valid(cv::Point(static_cast<int>(std::ceil(last_valid_.x * rx)),
                                 static_cast<int>(std::ceil(last_valid_.y * ry))),
                       cv::Point(static_cast<int>(last_valid_.br().x * rx),
                                 static_cast<int>(last_valid_.br().y * ry)));
  reset();
  last_ = resized;
  last_valid_ = valid & cv::Rect({0, 0}, size);
}

void DenseFlow::reset() {
  // A new DIS too: OpenCV 4.6's keeps buffers of the sizes it has seen, and one reused on frames
  // of another size after a few of a smaller one crashed in its parallel loop (tests/gst's flow
  // model through a new resolution and a reset).
  dis_.release();
  last_.release();
  last_valid_ = cv::Rect();
  last_halved_ = false;
  flow_.release();
  measured_ = cv::Rect();
}

}  // namespace projtrack
