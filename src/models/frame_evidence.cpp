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
  const int held = scales_[0] == scale ? 0 : scales_[1] == scale ? 1 : -1;
  const int slot = held >= 0 ? held : older_;
  WorkImages& img = slots_[slot];
  if (held >= 0 && (img.filled & wanted) == wanted) return &img;
  // What this frame holds already at this scale is kept: the part asked for joins it.
  if (held >= 0) wanted |= img.filled;
  const std::uint64_t cost = images_cost(frame_part(wanted, scale, width(), height()), scale);
  if (budget.exhausted(cost)) return nullptr;
  budget.spend(cost);
  build_work_images(frame, scale, wanted, img);
  scales_[slot] = scale;
  if (held < 0) older_ = 1 - slot;
  return &img;
}

}  // namespace projtrack
