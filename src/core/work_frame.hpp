// A region of the frame at a coarser working scale: what the object model and the finder read.
// Working on s×s blocks keeps their cost near constant whatever the frame's or the object's size
// (a 1080p object is as cheap as a 640×480 one); only the estimator reads full resolution.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "projtrack/color_view.hpp"
#include "projtrack/geometry.hpp"

namespace projtrack {

// Work coordinates: work pixel (X, Y) at scale s covers frame pixels [sX, sX + s) × [sY, sY + s).
class WorkFrame {
 public:
  // The work pixels of `region` (work coordinates, clipped to the frame): each luma the mean of
  // its block, each chroma the block's centre sample, both read with the frame's exposure. The
  // view's exposure is the identity.
  void build(const ColorView& frame, int scale, const Rect& region);
  // The region's pixels: view() pixel (x, y) is work pixel (x + rect().x, y + rect().y).
  const ColorView& view() const { return view_; }
  const Rect& rect() const { return rect_; }
  int scale() const { return scale_; }

 private:
  std::vector<std::uint8_t> planes_;
  std::vector<std::uint32_t> sums_;      // per block of a row
  std::vector<std::uint16_t> columns_;   // per frame column of a block row: its s pixels' sum
  std::vector<std::ptrdiff_t> offsets_;  // chroma offset of each block of a row
  std::array<std::uint8_t, 256> luma_lut_{}, chroma_lut_{};  // the frame's exposure
  ColorView view_;
  Rect rect_;
  int scale_ = 1;
};

// The work scale that makes `pixels` frame pixels about `target` work pixels (at least 1).
int work_scale(double pixels, double target);
// The work rectangle of a frame rectangle (every block it touches), and back (the blocks' pixels,
// clipped to a width × height frame).
Rect to_work(const Rect& frame_rect, int scale);
Rect to_frame(const Rect& work_rect, int scale, int width, int height);

}  // namespace projtrack
