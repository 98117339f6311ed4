#include "alpha_mask.hpp"

#include <algorithm>
#include <cstdint>

namespace projtrack::gst {

bool has_alpha(GstVideoFormat format) {
  switch (format) {
    case GST_VIDEO_FORMAT_AYUV:
    case GST_VIDEO_FORMAT_A420:
    case GST_VIDEO_FORMAT_BGRA:
    case GST_VIDEO_FORMAT_RGBA:
    case GST_VIDEO_FORMAT_ARGB:
    case GST_VIDEO_FORMAT_ABGR:
      return true;
    default:
      return false;
  }
}

namespace {

// Sets to 255 the alpha of `row` (frame row y) where silhouette `s` covers it.
void cut_out_row(std::uint8_t* row, int y, int width, int pstride, const SilhouetteMask& s) {
  if (s.empty()) return;
  const int wy = y / s.scale - s.rect.y;
  if (wy < 0 || wy >= s.mask.height) return;
  const std::uint8_t* in = s.mask.row(wy);
  // Each work pixel inside sets its s columns (those in the frame).
  for (int wx = 0; wx < s.mask.width; ++wx) {
    if (!in[wx]) continue;
    const long long x0 = (static_cast<long long>(s.rect.x) + wx) * s.scale;
    const int from = static_cast<int>(std::clamp<long long>(x0, 0, width));
    const int to = static_cast<int>(std::clamp<long long>(x0 + s.scale, 0, width));
    for (int x = from; x < to; ++x) row[static_cast<std::ptrdiff_t>(x) * pstride] = 255;
  }
}

}  // namespace

void write_alpha(GstVideoFrame* frame, const std::vector<SilhouetteMask>& silhouettes) {
  const int a = GST_VIDEO_COMP_A;
  auto* data = static_cast<std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, a));
  const int pstride = GST_VIDEO_FRAME_COMP_PSTRIDE(frame, a);
  const std::ptrdiff_t stride = GST_VIDEO_FRAME_COMP_STRIDE(frame, a);
  const int width = GST_VIDEO_FRAME_COMP_WIDTH(frame, a);
  const int height = GST_VIDEO_FRAME_COMP_HEIGHT(frame, a);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* row = data + y * stride;
    for (int x = 0; x < width; ++x) row[static_cast<std::ptrdiff_t>(x) * pstride] = 0;
    for (const SilhouetteMask& s : silhouettes) cut_out_row(row, y, width, pstride, s);
  }
}

}  // namespace projtrack::gst
