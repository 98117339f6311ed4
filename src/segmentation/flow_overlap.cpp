// Where a followed object's cut meets another object's (MultiTracker): its evidence there, and
// the cut without the pixels the object in front owns.
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "segmentation/flow_segmenter.hpp"

namespace projtrack {

namespace {

// Calls f(x, y) for each work pixel of `area` (work px at `scale`) whose centre lies in `pixels`.
template <class F>
void each_shared(const cv::Rect& area, int scale, const FramePixels& pixels, F&& f) {
  const cv::Rect frame_box(pixels.origin.x / scale, pixels.origin.y / scale,
                           pixels.mask.cols * pixels.step / scale + 2,
                           pixels.mask.rows * pixels.step / scale + 2);
  const cv::Rect r = area & frame_box;
  for (int y = r.y; y < r.br().y; ++y)
    for (int x = r.x; x < r.br().x; ++x)
      if (pixels.contains(x * scale + scale / 2, y * scale + scale / 2)) f(x, y);
}

}  // namespace

double FlowSegmenter::evidence_over(const FramePixels& pixels) const {
  if (mask_.empty() || reach_.empty() || pixels.empty()) return -HUGE_VAL;
  double sum = 0;
  int n = 0;
  each_shared(reach_, scale_, pixels, [&](int x, int y) {
    sum += log_odds_.at<float>(y, x) - prior_odds_.at<float>(y - reach_.y, x - reach_.x);
    ++n;
  });
  return n > 0 ? sum / n : -HUGE_VAL;
}

bool FlowSegmenter::give_up(const FramePixels& pixels) {
  if (mask_.empty() || box_.empty()) return false;
  each_shared(box_, scale_, pixels, [&](int x, int y) { mask_.at<std::uint8_t>(y, x) = 0; });
  const cv::Rect left = support_of(mask_(box_), support_);
  if (left.empty()) return false;  // the verdict (refuse()) brings back the last silhouette
  box_ = left + box_.tl();
  return true;
}

}  // namespace projtrack
