#include "models/frame_evidence.hpp"

#include <algorithm>

namespace projtrack {

std::uint64_t FrameEvidence::images_cost(const cv::Rect& part, int scale) {
  const auto pixels = static_cast<std::uint64_t>(std::max(part.area(), 0));
  const auto s = static_cast<std::uint64_t>(std::max(scale, 1));
  return pixels + 4 * pixels / (s * s);
}

const WorkImages* FrameEvidence::images(int scale, const cv::Rect& region) {
  const cv::Rect work({0, 0}, work_size(width(), height(), scale));
  cv::Rect wanted = region.empty() ? work : region & work;
  int slot = -1;
  for (std::size_t k = 0; k < scales_.size(); ++k) {
    if (scales_[k] != scale) continue;
    const cv::Rect& filled = slots_[k].filled;
    if ((filled & wanted) == wanted) return &slots_[k];
    // What this frame holds already at this scale is kept, and the part asked for joins it,
    // unless the two lie apart (objects far from each other): the box around both would build
    // more than the two, so the part asked for takes a slot of its own.
    const cv::Rect both = filled | wanted;
    if (slot < 0 && both.area() <= filled.area() + wanted.area()) {
      slot = static_cast<int>(k);
      wanted = both;
    }
  }
  if (slot < 0) slot = free_slot();
  const std::uint64_t cost = images_cost(frame_part(wanted, scale, width(), height()), scale);
  if (budget.exhausted(cost)) return nullptr;
  budget.spend(cost);
  build_work_images(frame, scale, wanted, slots_[slot]);
  scales_[slot] = scale;
  return &slots_[slot];
}

int FrameEvidence::free_slot() {
  // A slot no scale holds on this frame (its buffers from an earlier frame are reused), else a
  // new one, which leaves the slots returned before where they are (a deque).
  const auto none = std::find(scales_.begin(), scales_.end(), 0);
  if (none != scales_.end()) return static_cast<int>(none - scales_.begin());
  slots_.emplace_back();
  scales_.push_back(0);
  return static_cast<int>(slots_.size()) - 1;
}

}  // namespace projtrack
