// The silhouette's outline as polygons: OpenCV's border following (Suzuki & Abe) and
// Douglas-Peucker simplification, in work pixels, then moved into the frame.
#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "projtrack/silhouette_mask.hpp"

namespace projtrack {

std::vector<std::vector<Point2i>> outline_polygons(const SilhouetteMask& s, double tolerance) {
  std::vector<std::vector<Point2i>> out;
  if (s.empty()) return out;
  // A copy with a zero border: findContours needs a writable 8-bit image and treats the border
  // as background, so a piece touching the mask's edge is still closed.
  cv::Mat padded(s.mask.height + 2, s.mask.width + 2, CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < s.mask.height; ++y) {
    const std::uint8_t* in = s.mask.row(y);
    std::uint8_t* o = padded.ptr<std::uint8_t>(y + 1) + 1;
    for (int x = 0; x < s.mask.width; ++x) o[x] = in[x] ? 255 : 0;
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(padded, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  std::sort(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
    return std::abs(cv::contourArea(a)) > std::abs(cv::contourArea(b));
  });
  const double epsilon = std::max(0.0, tolerance);
  const auto to_frame = [&](int work, int origin, int size) {
    const long long v = (static_cast<long long>(work) - 1 + origin) * s.scale + s.scale / 2;
    return static_cast<int>(std::clamp<long long>(v, 0, std::max(0, size - 1)));
  };
  for (const std::vector<cv::Point>& c : contours) {
    std::vector<cv::Point> poly;
    cv::approxPolyDP(c, poly, epsilon, true);
    std::vector<Point2i>& p = out.emplace_back();
    p.reserve(poly.size());
    for (const cv::Point& q : poly)
      p.push_back(
          {to_frame(q.x, s.rect.x, s.frame_width), to_frame(q.y, s.rect.y, s.frame_height)});
  }
  return out;
}

}  // namespace projtrack
