#include "edges/edge_source.hpp"

namespace projtrack {

ImageView EdgeSource::region(const Rect& r) {
  if (map_) return map_->detect(gray_, params_, r, budget_);
  const ImageView& f = given_;
  const Rect c = clip_to_frame(r, f.width, f.height);
  if (!f.valid() || c.empty()) return {};
  return ImageView(f.row(c.y) + c.x, c.width, c.height, f.stride);
}

ImageView EdgeSource::work(const WorkFrame& wf, EdgeMap& map,
                           std::vector<std::uint8_t>& buffer) const {
  // Not charged to the budget: a work frame is bounded by the work scale (WorkFrame), whatever
  // the frame's size or content.
  if (map_) return map.detect(wf.view().luma, params_);
  const Rect& r = wf.rect();
  const int s = wf.scale();
  buffer.assign(static_cast<std::size_t>(r.width) * r.height, 0);
  const Rect frame_part = to_frame(r, s, given_.width, given_.height);
  for (int y = frame_part.y; y < frame_part.bottom(); ++y) {
    const std::uint8_t* e = given_.row(y);
    std::uint8_t* out = buffer.data() + static_cast<std::size_t>(y / s - r.y) * r.width;
    for (int x = frame_part.x; x < frame_part.right(); ++x)
      if (e[x]) out[x / s - r.x] = 255;
  }
  return ImageView(buffer.data(), r.width, r.height, r.width);
}

}  // namespace projtrack
