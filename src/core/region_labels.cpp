#include "core/region_labels.hpp"

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
  parent_.assign(1, 0);
  runs_.clear();
  // Pass 1: each row's runs of foreground get a provisional label each, merged with the runs of
  // the row above that they touch (4-connectivity: overlapping columns).
  std::size_t above_begin = 0, above_end = 0;
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* in = image.row(y);
    const std::size_t begin = runs_.size();
    std::size_t a = above_begin;
    for (int x = 0; x < width_;) {
      if ((in[x] == 0) != foreground_is_zero) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < width_ && (in[x] == 0) == foreground_is_zero) ++x;
      const int x1 = x - 1;
      std::int32_t label = static_cast<std::int32_t>(parent_.size());
      parent_.push_back(label);
      while (a < above_end && runs_[a].x1 < x0) ++a;
      for (std::size_t k = a; k < above_end && runs_[k].x0 <= x1; ++k) {
        const std::int32_t p = find(runs_[k].label), q = find(label);
        if (p != q) parent_[p < q ? q : p] = p < q ? p : q;
      }
      runs_.push_back({y, x0, x1, label});
    }
    above_begin = begin;
    above_end = runs_.size();
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
  std::fill_n(labels_.begin(), n, 0);
  for (const Run& r : runs_) {
    const std::int32_t l = final_[r.label];
    std::fill_n(labels_.begin() + static_cast<std::ptrdiff_t>(r.y) * width_ + r.x0, r.x1 - r.x0 + 1,
                l);
    sizes_[l] += r.x1 - r.x0 + 1;
  }
}

}  // namespace projtrack
