// numpy frames as the library's ColorView: gray (H×W or H×W×1) or BGR / BGRA (H×W×3 or H×W×4)
// uint8, of any strides. Gray rows are read in place when their pixels are adjacent; colour is
// converted once to luma and chroma planes by the library's own conversion (the element's, for
// packed RGB), reading any row stride, and an array of another layout is copied first.
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
  std::vector<std::uint8_t> planes_;  // BGR's luma, then its U and V planes
  int channels_ = 0;
};

}  // namespace projtrack::python
