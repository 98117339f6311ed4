// A frame's colour, read in place: its luma plane and, when it has them, its two chroma planes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "exposure.hpp"
#include "image_view.hpp"

namespace projtrack {

// The chroma (Cb = U, Cr = V) of a YUV frame as its formats store it: planar (I420, YV12, Y42B,
// Y444: pixel stride 1) or interleaved (NV12, NV21: pixel stride 2), at full or subsampled
// resolution (shift_x, shift_y: 1 for half). Non-owning, like ImageView.
struct ChromaView {
  const std::uint8_t* u = nullptr;
  const std::uint8_t* v = nullptr;
  std::ptrdiff_t stride = 0;  // bytes from one chroma row to the next
  int pixel_stride = 1;       // bytes from one chroma sample to the next in a row
  int shift_x = 0, shift_y = 0;

  bool empty() const { return u == nullptr || v == nullptr; }
  // The chroma of the frame pixel (x, y).
  std::uint8_t u_at(int x, int y) const { return u[offset(x, y)]; }
  std::uint8_t v_at(int x, int y) const { return v[offset(x, y)]; }
  std::ptrdiff_t offset(int x, int y) const {
    return static_cast<std::ptrdiff_t>(y >> shift_y) * stride +
           static_cast<std::ptrdiff_t>(x >> shift_x) * pixel_stride;
  }
};

// The one range of the values the tracker reads: video range (BT.601's studio swing: luma
// 16–235, chroma 16–240 about 128), what cameras and decoders give as YUV. Every frame is read at
// it, so that every pixel format of one picture gives the same colours: the element and Python
// convert RGB to it and map a full-range frame (GRAY8, JPEG's YUV, OpenCV's gray) down to it
// (color_conversion.hpp).
inline constexpr int kVideoBlack = 16;  // video range's black luma (and an edge map's "no edge")

// A frame's colours at video range (above).
struct ColorView {
  ImageView luma;
  ChromaView chroma;  // empty for gray frames: only luma tells colours apart
  // How these colours are to be read in dim light (exposure.hpp): carried with the frame, but no
  // stage applies it since the appearance model, which did, was removed.
  Exposure exposure;

  bool has_chroma() const { return !chroma.empty(); }
};

}  // namespace projtrack
