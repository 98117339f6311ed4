#include "edges/edge_source.hpp"

namespace projtrack {

ImageView EdgeSource::region(const Rect& r) {
  if (map_) return map_->detect(gray_, params_, r, budget_);
  const ImageView& f = given_;
  const Rect c = clip_to_frame(r, f.width, f.height);
  if (!f.valid() || c.empty()) return {};
  return ImageView(f.row(c.y) + c.x, c.width, c.height, f.stride);
}

}  // namespace projtrack
