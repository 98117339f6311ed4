#include "acquisition/motion_detector.hpp"

#include <algorithm>
#include <cstdlib>

#include "projtrack/exposure.hpp"

namespace projtrack {

bool MotionDetector::update(const ImageView& gray, const Params& p, Motion& out) {
  out.fraction = 0;
  out.centroid = {};
  out.points.clear();
  if (!gray.valid()) return false;
  const int step = std::max(1, p.step);
  const int cols = (gray.width + step - 1) / step, rows = (gray.height + step - 1) / step;
  const bool comparable = gray.width == width_ && gray.height == height_ && step == step_;
  previous_.resize(static_cast<std::size_t>(cols) * rows);
  histogram_.fill(0);
  double sx = 0, sy = 0;
  changed_.resize(static_cast<std::size_t>(cols));
  // Room for every sample at once: the list never grows (and copies itself) mid-frame.
  out.points.reserve(static_cast<std::size_t>(cols) * rows);
  const int threshold = comparable ? p.threshold : 255;  // the first frame: nothing changed
  for (int r = 0; r < rows; ++r) {
    const std::uint8_t* row = gray.row(r * step);
    std::uint8_t* prev = previous_.data() + static_cast<std::size_t>(r) * cols;
    // The row's changed columns are listed without a branch (on a noisy frame whether a sample
    // changed is a coin toss, which a branch predictor loses), then appended in one pass.
    int n = 0;
    for (int c = 0; c < cols; ++c) {
      const std::uint8_t v = row[c * step];
      changed_[n] = c;
      n += std::abs(v - prev[c]) > threshold;
      prev[c] = v;
      ++histogram_[v];
    }
    if (!n) continue;
    const std::size_t at = out.points.size();
    out.points.resize(at + n);
    Point2i* q = out.points.data() + at;
    for (int i = 0; i < n; ++i) {
      q[i].x = changed_[i] * step;
      q[i].y = r * step;
      sx += q[i].x;
    }
    sy += static_cast<double>(n) * r * step;
  }
  spread_ = luma_range(histogram_).spread();
  width_ = gray.width;
  height_ = gray.height;
  step_ = step;
  out.step = step;
  if (!comparable) return false;
  out.fraction = static_cast<double>(out.points.size()) / (static_cast<double>(cols) * rows);
  if (!out.points.empty()) out.centroid = {sx / out.points.size(), sy / out.points.size()};
  return true;
}

}  // namespace projtrack
