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

// The chroma samples [first, first + count) along one axis that cover a block of `pixels`
// frame pixels: the first and last cover `first_weight` and `last_weight` of them, the others
// `inner` each.
struct ChromaSpan {
  int first = 0, count = 0, pixels = 0, inner = 1, first_weight = 0, last_weight = 0;
};

// Work coordinates: work pixel (X, Y) at scale s covers frame pixels [sX, sX + s) × [sY, sY + s).
class WorkFrame {
 public:
  // The work pixels of `region` (work coordinates, clipped to the frame): each luma the mean of
  // its block, each chroma the mean over its block's pixels of the chroma sample covering
  // each, both read with the frame's exposure. The
  // view's exposure is the identity.
  void build(const ColorView& frame, int scale, const Rect& region);
  // The region's pixels: view() pixel (x, y) is work pixel (x + rect().x, y + rect().y).
  const ColorView& view() const { return view_; }
  const Rect& rect() const { return rect_; }
  int scale() const { return scale_; }

 private:
  std::vector<std::uint8_t> planes_;
  std::vector<std::uint32_t> sums_;         // per block of a row
  std::vector<std::uint16_t> columns_;      // per frame column of a block row: its s pixels' sum
  std::vector<ChromaSpan> spans_;           // chroma columns of each block of a row
  std::vector<std::uint32_t> chroma_sums_;  // per chroma column of a block row: weighted Cb, Cr
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
