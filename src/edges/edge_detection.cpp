#include "projtrack/edge_detection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <opencv2/imgproc.hpp>

#include "edges/box_blur.hpp"
#include "edges/canny.hpp"
#include "projtrack/work_budget.hpp"

namespace projtrack {

EdgeMap::EdgeMap() : canny_(std::make_unique<CannyDetector>()) {}
EdgeMap::~EdgeMap() = default;
EdgeMap::EdgeMap(EdgeMap&&) noexcept = default;
EdgeMap& EdgeMap::operator=(EdgeMap&&) noexcept = default;

namespace {

cv::Mat wrap(const ImageView& v) {
  // cv::Mat has no const view; the input is only ever read.
  return cv::Mat(v.height, v.width, CV_8UC1, const_cast<std::uint8_t*>(v.data),
                 static_cast<std::size_t>(v.stride));
}

ImageView view_of(const cv::Mat& m) {
  return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
}

}  // namespace

ImageView EdgeMap::detect(const ImageView& gray, const EdgeParams& params) {
  return detect(gray, params, Rect{0, 0, gray.width, gray.height});
}

template <class T>
cv::Mat EdgeMap::wrap_buffer(std::vector<T>& buffer, int rows, int cols, int type) {
  const std::size_t n = static_cast<std::size_t>(rows) * cols;
  if (buffer.size() < n) buffer.resize(n);
  return cv::Mat(rows, cols, type, buffer.data());  // standalone: filters see no pixels beyond
}

ImageView EdgeMap::detect(const ImageView& gray, const EdgeParams& params, const Rect& region,
                          WorkBudget* budget) {
  if (!gray.valid()) return {};
  const Rect r = clip_to_frame(region, gray.width, gray.height);
  if (r.empty()) return {};
  const int x0 = r.x, y0 = r.y, rows = r.height, cols = r.width;
  if (params.detector == EdgeDetector::Input && params.input_black_level <= 0)
    return ImageView(gray.row(y0) + x0, cols, rows, gray.stride);
  const ImageView in_region(gray.row(y0) + x0, cols, rows, gray.stride);
  // The budget's charge for one pass over the region's pixels by a vectorised filter.
  const std::uint64_t pass = static_cast<std::uint64_t>(rows) * cols / kScannedPixelsPerCost;
  // Out of work: a region without edges (the caller's budget says it is incomplete).
  const auto none = [&] {
    cv::Mat edges = wrap_buffer(edges_, rows, cols, CV_8UC1);
    edges.setTo(0);
    return view_of(edges);
  };
  if (params.detector == EdgeDetector::Input) {
    if (budget) {
      if (budget->exhausted(pass)) return none();
      budget->spend(pass);
    }
    cv::Mat edges = wrap_buffer(edges_, rows, cols, CV_8UC1);
    cv::threshold(wrap(in_region), edges, std::min(params.input_black_level, 255), 255,
                  cv::THRESH_BINARY);
    return view_of(edges);
  }

  const int passes = std::clamp(params.blur, 0, kMaxBlurPasses);
  ImageView blurred = in_region;
  for (int i = 0; i < passes; ++i) {
    if (budget) {  // nine reads a pixel, in two separable passes
      if (budget->exhausted(2 * pass)) return none();
      budget->spend(2 * pass);
    }
    // The first pass reads the frame around the region; later ones replicate the region's border.
    cv::Mat dst = wrap_buffer(blurred_[i % 2], rows, cols, CV_8UC1);
    if (i == 0)
      box_blur3(gray, r, dst.data, static_cast<std::ptrdiff_t>(dst.step));
    else
      box_blur3(blurred, Rect{0, 0, cols, rows}, dst.data, static_cast<std::ptrdiff_t>(dst.step));
    blurred = view_of(dst);
  }
  const double low = std::max(0.0, params.low);
  const double high = std::max(0.0, params.high);

  if (params.detector == EdgeDetector::Canny) {
    return canny_->detect(blurred, low, high, budget);
  }
  if (budget) {  // two Sobel filters in 16 bits, then the threshold
    if (budget->exhausted(8 * pass)) return none();
    budget->spend(8 * pass);
  }
  // Canny keeps its own map; only Sobel writes into edges_.
  cv::Mat edges = wrap_buffer(edges_, rows, cols, CV_8UC1);
  const cv::Mat src = wrap(blurred);
  cv::Mat gx = wrap_buffer(gx_, rows, cols, CV_16SC1), gy = wrap_buffer(gy_, rows, cols, CV_16SC1);
  cv::Sobel(src, gx, CV_16S, 1, 0, 3, 1, 0, cv::BORDER_REPLICATE);
  cv::Sobel(src, gy, CV_16S, 0, 1, 3, 1, 0, cv::BORDER_REPLICATE);
  const int threshold = static_cast<int>(std::min(low, 1e9));
  for (int y = 0; y < rows; ++y) {
    const std::int16_t* dx = gx.ptr<std::int16_t>(y);
    const std::int16_t* dy = gy.ptr<std::int16_t>(y);
    std::uint8_t* e = edges.ptr<std::uint8_t>(y);
    for (int x = 0; x < cols; ++x) e[x] = std::abs(dx[x]) + std::abs(dy[x]) >= threshold ? 255 : 0;
  }
  return view_of(edges);
}

std::string validate(const EdgeParams& params) {
  if (!std::isfinite(params.low))
    return "edge_threshold_low = " + std::to_string(params.low) + " must be a number of at least 0";
  if (!std::isfinite(params.high))
    return "edge_threshold_high = " + std::to_string(params.high) +
           " must be a number of at least 0";
  if (params.detector == EdgeDetector::Canny && params.low > params.high) {
    char why[160];
    std::snprintf(why, sizeof why,
                  "edge-threshold-low %g is above edge-threshold-high %g: Canny needs low <= high",
                  params.low, params.high);
    return why;
  }
  return {};
}

}  // namespace projtrack
