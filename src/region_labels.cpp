#include "region_labels.hpp"

namespace projtrack {

std::int32_t RegionLabels::find(std::int32_t a) {
  while (parent_[a] != a) {
    parent_[a] = parent_[parent_[a]];  // path halving
    a = parent_[a];
  }
  return a;
}

void RegionLabels::label(const ImageView& image, bool foreground_is_zero) {
  width_ = image.valid() ? image.width : 0;
  height_ = image.valid() ? image.height : 0;
  count_ = 0;
  const std::size_t n = static_cast<std::size_t>(width_) * height_;
  if (labels_.size() < n) labels_.resize(n);
  parent_.clear();
  parent_.push_back(0);
  // Pass 1: provisional labels from the left and upper neighbours, equivalences merged.
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* in = image.row(y);
    std::int32_t* out = labels_.data() + static_cast<std::size_t>(y) * width_;
    const std::int32_t* up = y > 0 ? out - width_ : nullptr;
    for (int x = 0; x < width_; ++x) {
      if ((in[x] == 0) != foreground_is_zero) {
        out[x] = 0;
        continue;
      }
      const std::int32_t left = x > 0 ? out[x - 1] : 0, above = up ? up[x] : 0;
      if (left && above) {
        const std::int32_t a = find(left), b = find(above);
        out[x] = a < b ? a : b;
        if (a != b) parent_[a < b ? b : a] = a < b ? a : b;
      } else if (left || above) {
        out[x] = left ? left : above;
      } else {
        out[x] = static_cast<std::int32_t>(parent_.size());
        parent_.push_back(out[x]);
      }
    }
  }
  // Every provisional label points at a smaller one or itself, so one ascending pass flattens the
  // forest; roots then get consecutive labels.
  final_.resize(parent_.size());
  final_[0] = 0;
  for (std::size_t i = 1; i < parent_.size(); ++i) {
    parent_[i] = parent_[parent_[i]];
    final_[i] = parent_[i] == static_cast<std::int32_t>(i) ? ++count_ : final_[parent_[i]];
  }
  sizes_.assign(static_cast<std::size_t>(count_) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!labels_[i]) continue;
    labels_[i] = final_[labels_[i]];
    ++sizes_[labels_[i]];
  }
}

}  // namespace projtrack
