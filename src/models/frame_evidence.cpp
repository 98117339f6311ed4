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
  const auto at = std::find(scales_.begin(), scales_.end(), scale);
  const int held = at == scales_.end() ? -1 : static_cast<int>(at - scales_.begin());
  const int slot = held >= 0 ? held : free_slot();
  WorkImages& img = slots_[slot];
  if (held >= 0 && (img.filled & wanted) == wanted) return &img;
  // What this frame holds already at this scale is kept: the part asked for joins it.
  if (held >= 0) wanted |= img.filled;
  const std::uint64_t cost = images_cost(frame_part(wanted, scale, width(), height()), scale);
  if (budget.exhausted(cost)) return nullptr;
  budget.spend(cost);
  build_work_images(frame, scale, wanted, img);
  scales_[slot] = scale;
  return &img;
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
