// The silhouette out of the tracker: the object model's mask (work coordinates) at full
// resolution, as the estimator saw it (each work pixel an s×s block, clipped to the frame).
#include <cstring>

#include "tracker/tracker_impl.hpp"

namespace projtrack {

bool Tracker::silhouette(std::uint8_t* mask, int width, int height, std::ptrdiff_t stride) const {
  if (mask == nullptr || width <= 0 || height <= 0 || stride < width) return false;
  for (int y = 0; y < height; ++y) std::memset(mask + y * stride, 0, width);
  const SilhouetteModel& object = impl_->state.object;
  if (impl_->state.model() != ObjectModelKind::Appearance || !object.tracking()) return false;
  const Mask& m = object.silhouette();
  const int s = object.scale();
  const Rect r = to_frame(m.rect(), s, width, height);
  for (int y = r.y; y < r.bottom(); ++y) {
    const std::uint8_t* in = m.row(y / s - m.rect().y);
    std::uint8_t* out = mask + y * stride;
    for (int x = r.x; x < r.right(); ++x) out[x] = in[x / s - m.rect().x] ? 255 : 0;
  }
  return true;
}

}  // namespace projtrack
