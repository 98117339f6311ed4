// A frame-sized byte mask that the fills and rasterizers reuse from frame to frame.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "projtrack/geometry.hpp"

namespace projtrack {

// Invariant between uses: all zero. A user sets bytes, then clears the rectangle it touched, so
// the cost per frame follows the object's size, not the frame's, and nothing is allocated once
// the frame size is stable.
class ScratchMask {
 public:
  void ensure(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    data_.assign(static_cast<std::size_t>(width) * height, 0);
  }
  std::uint8_t* row(int y) { return data_.data() + static_cast<std::size_t>(y) * width_; }
  const std::uint8_t* row(int y) const {
    return data_.data() + static_cast<std::size_t>(y) * width_;
  }
  int stride() const { return width_; }
  // Whether pixel `p` is set (false outside the mask).
  bool at(Point2i p) const {
    return p.x >= 0 && p.y >= 0 && p.x < width_ && p.y < height_ &&
           data_[static_cast<std::size_t>(p.y) * width_ + p.x];
  }
  void clear(const Rect& r) {
    for (int y = r.y; y < r.bottom(); ++y) std::memset(row(y) + r.x, 0, r.width);
  }

 private:
  std::vector<std::uint8_t> data_;
  int width_ = 0, height_ = 0;
};

}  // namespace projtrack
