// The 4-connected regions of a binary image, labelled run by run with union-find, on buffers
// kept between frames.
#pragma once

#include <cstdint>
#include <vector>

#include "projtrack/image_view.hpp"

namespace projtrack {

class RegionLabels {
 public:
  // Labels the pixels of `image` that are zero (`foreground_is_zero`: the free pixels of an edge
  // map) or non-zero (a mask): each region gets a label 1..count(), every other pixel 0.
  void label(const ImageView& image, bool foreground_is_zero);
  int count() const { return count_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const std::int32_t* row(int y) const {
    return labels_.data() + static_cast<std::size_t>(y) * width_;
  }
  // Pixels in region `l` (1..count()).
  std::int32_t size(int l) const { return sizes_[l]; }

 private:
  std::int32_t find(std::int32_t a);
  struct Run {
    int y, x0, x1;  // a row's foreground pixels x0..x1
    std::int32_t label;
  };
  std::vector<Run> runs_;
  std::vector<std::int32_t> labels_, parent_, final_, sizes_;
  int width_ = 0, height_ = 0, count_ = 0;
};

}  // namespace projtrack
