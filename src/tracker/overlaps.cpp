#include "tracker/overlaps.hpp"

#include <algorithm>

namespace projtrack {

cv::Rect frame_rect(const SilhouetteMask& s) {
  const cv::Rect r(s.rect.x * s.scale, s.rect.y * s.scale, s.rect.width * s.scale,
                   s.rect.height * s.scale);
  return r & cv::Rect(0, 0, s.frame_width, s.frame_height);
}

bool covers_half_of(const SilhouetteMask& s, const Rect& box) {
  const cv::Rect b(box.x, box.y, box.width, box.height);
  return !s.empty() && (frame_rect(s) & b).area() * 2 >= b.area();
}

double silhouette_area(const SilhouetteMask& s) {
  if (s.empty()) return 0;
  double n = 0;
  for (int y = 0; y < s.mask.height; ++y)
    for (int x = 0; x < s.mask.width; ++x) n += s.mask.at(x, y) != 0;
  return n * s.scale * s.scale;
}

FramePixels shared_pixels(const SilhouetteMask& a, const SilhouetteMask& b) {
  FramePixels both;
  if (a.empty() || b.empty()) return both;
  const cv::Rect r = frame_rect(a) & frame_rect(b);
  if (r.empty()) return both;
  both.step = std::min(a.scale, b.scale);
  both.origin = r.tl();
  both.mask.create((r.height + both.step - 1) / both.step, (r.width + both.step - 1) / both.step,
                   CV_8U);
  for (int my = 0; my < both.mask.rows; ++my) {
    std::uint8_t* row = both.mask.ptr<std::uint8_t>(my);
    const int y = std::min(r.y + my * both.step + both.step / 2, r.br().y - 1);
    for (int mx = 0; mx < both.mask.cols; ++mx) {
      const int x = std::min(r.x + mx * both.step + both.step / 2, r.br().x - 1);
      row[mx] = a.contains({x, y}) && b.contains({x, y}) ? 255 : 0;
      both.count += row[mx] != 0;
    }
  }
  return both;
}

}  // namespace projtrack
