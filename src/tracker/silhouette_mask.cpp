// The silhouette out of the tracker: the object model's mask (work coordinates) at full
// resolution, as the estimator saw it (each work pixel an s×s block, clipped to the frame).
#include <algorithm>
#include <cstring>

#include "tracker/tracker_impl.hpp"

namespace projtrack {

namespace {

// `s` at full resolution into a mask of its frame's size (already cleared); false when empty.
bool draw(const SilhouetteMask& s, std::uint8_t* mask, std::ptrdiff_t stride) {
  if (s.empty()) return false;
  const Rect r = to_frame(s.rect, s.scale, s.frame_width, s.frame_height);
  // A work row is drawn once, into the first frame row it covers; its other rows copy that one.
  const std::uint8_t* drawn = nullptr;
  for (int y = r.y; y < r.bottom(); ++y) {
    std::uint8_t* out = mask + y * stride;
    if (drawn != nullptr && y % s.scale != 0) {
      std::memcpy(out + r.x, drawn + r.x, static_cast<std::size_t>(r.width));
      continue;
    }
    const std::uint8_t* in = s.mask.row(y / s.scale - s.rect.y) - s.rect.x;
    for (int x = r.x, wx = r.x / s.scale; x < r.right(); ++wx) {
      const std::uint8_t v = in[wx] ? 255 : 0;
      for (const int end = std::min(r.right(), (wx + 1) * s.scale); x < end; ++x) out[x] = v;
    }
    drawn = out;
  }
  return true;
}

}  // namespace

bool Tracker::silhouette(std::uint8_t* mask, int width, int height, std::ptrdiff_t stride) const {
  if (mask == nullptr || width <= 0 || height <= 0 || stride < width) return false;
  for (int y = 0; y < height; ++y) std::memset(mask + y * stride, 0, width);
  SilhouetteMask s = impl_->object.model->silhouette(width, height);
  s.frame_width = width;  // the caller's mask bounds what is drawn
  s.frame_height = height;
  return draw(s, mask, stride);
}

}  // namespace projtrack
