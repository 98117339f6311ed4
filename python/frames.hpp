// numpy frames as the library's ColorView: gray (H×W or H×W×1) or BGR / BGRA (H×W×3 or H×W×4)
// uint8, of any strides, read at the tracker's video range as the element reads GRAY8 and BGR:
// gray mapped from full range, colour converted to luma and chroma planes, both by the library's
// own conversions (the element's), reading any row stride; an array of another layout is copied
// first.
#pragma once

#include <pybind11/numpy.h>

#include <cstdint>
#include <vector>

#include "projtrack/color_view.hpp"

namespace projtrack::python {

// The largest side of a frame taken, px: 16384² pixels still count in 32 bits.
inline constexpr int kMaxSide = 16384;

class FrameReader {
 public:
  // The frame `obj` as the library reads it, valid until the next call (or the reader's end):
  // the reader holds the array (or its copy) and the converted planes. Throws TypeError for
  // what is not a numpy array of uint8, ValueError for a shape that is no frame.
  ColorView read(const pybind11::handle& obj);
  // The last frame's channels: 1 (gray), 3 (BGR) or 4 (BGRA); its kind, as the element's format.
  int channels() const { return channels_; }

 private:
  pybind11::array held_;              // the array read in place, kept alive while it is read
  std::vector<std::uint8_t> planes_;  // the luma, then BGR's U and V planes
  int channels_ = 0;
};

}  // namespace projtrack::python
