#include "motion/motion_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace projtrack {

cv::Rect support_of(const cv::Mat& values, cv::Mat& buffer) {
  cv::compare(values, 0, buffer, cv::CMP_GT);
  return cv::boundingRect(buffer);
}

cv::Rect grown_within(const cv::Rect& r, int by, cv::Size size) {
  return cv::Rect(r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by) & cv::Rect({0, 0}, size);
}

cv::Rect square_ring(const cv::Mat& inside, int width, cv::Mat& count, cv::Mat& around) {
  const cv::Rect near = grown_within(cv::boundingRect(inside), width, inside.size());
  const cv::Mat in = inside(near);
  cv::boxFilter(in, count, CV_32S, {2 * width + 1, 2 * width + 1}, {-1, -1}, false,
                cv::BORDER_CONSTANT | cv::BORDER_ISOLATED);
  cv::compare(count, 0, around, cv::CMP_GT);
  around.setTo(0, in);
  return near;
}

float largest_component(const cv::Mat& flow) {
  float largest = 0;
  for (int y = 0; y < flow.rows; ++y) {
    const float* f = flow.ptr<float>(y);
    const int n = flow.cols * flow.channels();
    int x = 0;
#if CV_SIMD
    // OpenCV 4.6's norm(NORM_INF) of a two-channel image took 0.2 ms at 427×240; this 0.03.
    cv::v_float32 most = cv::vx_setzero_f32();
    for (; x + cv::v_float32::nlanes <= n; x += cv::v_float32::nlanes)
      most = cv::v_max(most, cv::v_abs(cv::vx_load(f + x)));
    largest = std::max(largest, cv::v_reduce_max(most));
#endif
    for (; x < n; ++x) largest = std::max(largest, std::abs(f[x]));
  }
  return largest;
}

cv::Rect carry_along_flow(const cv::Mat& last, const cv::Rect& held, const cv::Mat& flow,
                          const cv::Rect& moving, cv::Mat& map, cv::Mat& prior) {
  if (prior.size() != flow.size() || prior.type() != CV_32F)
    prior = cv::Mat::zeros(flow.size(), CV_32F);
  if (held.empty()) return {};
  // Only pixels that came from the last silhouette's box take a value: those within the box grown
  // by the largest motion. A flow with a non-finite value reaches anywhere.
  const float largest = largest_component(flow(moving & cv::Rect({0, 0}, flow.size())));
  const int reach = std::isfinite(largest) && largest < static_cast<float>(flow.cols + flow.rows)
                        ? static_cast<int>(std::ceil(largest)) + 1
                        : flow.cols + flow.rows;
  const cv::Rect to = grown_within(held, reach, flow.size());
  map.create(to.size(), CV_32FC2);
  for (int y = 0; y < to.height; ++y) {
    const cv::Point2f* f = flow.ptr<cv::Point2f>(to.y + y) + to.x;
    cv::Point2f* m = map.ptr<cv::Point2f>(y);
    for (int x = 0; x < to.width; ++x)
      m[x] = {static_cast<float>(to.x + x) + f[x].x, static_cast<float>(to.y + y) + f[x].y};
  }
  cv::Mat into = prior(to);
  cv::remap(last, into, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
  return to;
}

namespace {

// The median of each component of the flow where `where` is set, from at most ~4 000 samples
// (a regular subsample: the median of a region needs no more). `samples` is a buffer.
bool median_flow(const cv::Mat& flow, const cv::Mat& where, int count, std::vector<float>& samples,
                 cv::Point2f& out) {
  if (count == 0) return false;
  const int step = std::max(1, static_cast<int>(std::sqrt(count / 4000.0)));
  const std::size_t most = static_cast<std::size_t>((flow.rows + step - 1) / step) *
                           static_cast<std::size_t>((flow.cols + step - 1) / step);
  if (samples.size() < 2 * most) samples.resize(2 * most);  // only grows: no allocation a frame
  float* xs = samples.data();
  float* ys = xs + most;
  std::size_t n = 0;
  for (int y = 0; y < flow.rows; y += step) {
    const cv::Point2f* f = flow.ptr<cv::Point2f>(y);
    const std::uint8_t* w = where.ptr<std::uint8_t>(y);
    for (int x = 0; x < flow.cols; x += step)
      if (w[x]) xs[n] = f[x].x, ys[n++] = f[x].y;
  }
  if (n == 0) return false;
  const std::size_t mid = n / 2;
  std::nth_element(xs, xs + mid, xs + n);
  std::nth_element(ys, ys + mid, ys + n);
  out = {xs[mid], ys[mid]};
  return true;
}

}  // namespace

MotionSplit split_motion(const cv::Mat& flow, const cv::Mat& inside, double ring, cv::Mat& count,
                         cv::Mat& around, std::vector<float>& samples) {
  MotionSplit s;
  const int area = cv::countNonZero(inside);
  if (area == 0) return s;
  const int r = std::max(1, static_cast<int>(ring * std::sqrt(static_cast<double>(area))));
  const cv::Rect near = square_ring(inside, r, count, around);
  const cv::Mat in = inside(near), moved = flow(near);
  s.valid = median_flow(moved, in, area, samples, s.object) &&
            median_flow(moved, around, cv::countNonZero(around), samples, s.surroundings);
  if (s.valid) s.separation = static_cast<float>(cv::norm(s.object - s.surroundings));
  return s;
}

void add_motion_evidence(const cv::Mat& flow, const MotionSplit& split, double clamp,
                         double min_separation, cv::Mat& log_odds, const cv::Mat& damped,
                         double damped_share) {
  if (!split.valid || split.separation < min_separation) return;
  const float spread = 0.5f * split.separation;
  const float k = 1.0f / (2 * spread * spread), c = static_cast<float>(clamp);
  const cv::Point2f o = split.object, b = split.surroundings;
  const auto share = static_cast<float>(damped_share);
  for (int y = 0; y < flow.rows; ++y) {
    const cv::Point2f* f = flow.ptr<cv::Point2f>(y);
    float* l = log_odds.ptr<float>(y);
    const std::uint8_t* d = damped.empty() ? nullptr : damped.ptr<std::uint8_t>(y);
    for (int x = 0; x < flow.cols; ++x) {
      const cv::Point2f d_o = f[x] - o, d_b = f[x] - b;
      const float e = std::clamp((d_b.dot(d_b) - d_o.dot(d_o)) * k, -c, c);
      l[x] += d != nullptr && d[x] ? share * e : e;
    }
  }
}

}  // namespace projtrack
