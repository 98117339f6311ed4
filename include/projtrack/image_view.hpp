// A non-owning view of an 8-bit, single-channel image.
#pragma once

#include <cstddef>
#include <cstdint>

namespace projtrack {

// A frame's luma plane, an edge map or a mask, read in place: rows may be padded
// (stride >= width) and the view never copies, owns or frees the pixels.
struct ImageView {
  const std::uint8_t* data = nullptr;
  int width = 0;
  int height = 0;
  std::ptrdiff_t stride = 0;  // bytes from the start of one row to the next

  ImageView() = default;
  ImageView(const std::uint8_t* d, int w, int h, std::ptrdiff_t s)
      : data(d), width(w), height(h), stride(s) {}

  const std::uint8_t* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
  std::uint8_t at(int x, int y) const { return row(y)[x]; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  // No pixels: a 0×N or N×0 image or no data.
  bool empty() const { return width <= 0 || height <= 0 || data == nullptr; }
  // A readable shape: pixels present and rows at least `width` bytes apart.
  bool valid() const { return !empty() && stride >= width; }
};

}  // namespace projtrack
