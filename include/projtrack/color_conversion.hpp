// Packed RGB of any component order to 8-bit gray and chroma, for frames that have no YUV planes;
// packed YUV's luma into a plane. packed_rgb_to_color() is the entry point for an RGB frame (the
// element's RGB caps, Python's BGR arrays); the functions it calls are here for what reads a part.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "color_view.hpp"

namespace projtrack {

// The gray of one RGB pixel, (77·R + 150·G + 29·B + 128) / 256: BT.601's weights, full range.
constexpr std::uint8_t gray_of(int r, int g, int b) {
  return static_cast<std::uint8_t>((77 * r + 150 * g + 29 * b + 128) >> 8);
}

// gray_of() of every pixel. `r`, `g`, `b` point at the first pixel's components; `pixel_stride`
// is 3 or 4 bytes; rows of both images may be padded.
void packed_rgb_to_gray(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                        int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                        std::uint8_t* gray, std::ptrdiff_t gray_stride);

// One component of a packed format (YUY2's or UYVY's luma: every second byte) into a plane of
// its own; rows of both images may be padded (and run bottom-up: a negative `row_stride`). The
// images must not overlap. Pixel strides 1 and 2 are vectorised.
void gather_component(const std::uint8_t* first, int pixel_stride, std::ptrdiff_t row_stride,
                      int width, int height, std::uint8_t* out, std::ptrdiff_t out_stride);

// The chroma of one RGB pixel, BT.601 full range: Cb = U and Cr = V, 128 for a neutral colour.
constexpr std::uint8_t u_of(int r, int g, int b) {
  return static_cast<std::uint8_t>(((-43 * r - 85 * g + 128 * b + 128) >> 8) + 128);
}
constexpr std::uint8_t v_of(int r, int g, int b) {
  return static_cast<std::uint8_t>(((128 * r - 107 * g - 21 * b + 128) >> 8) + 128);
}

// u_of() and v_of() at half resolution, as I420 stores chroma: of the top-left pixel of every
// 2×2 block, into planes of (width + 1) / 2 × (height + 1) / 2 with row stride `chroma_stride`.
void packed_rgb_to_chroma(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                          int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                          std::uint8_t* u, std::uint8_t* v, std::ptrdiff_t chroma_stride);

// A packed RGB frame as the tracker reads it: its luma (packed_rgb_to_gray) and half-resolution
// chroma (packed_rgb_to_chroma) written into `planes` (resized to fit; reused from frame to
// frame, it allocates only when the frame grows), and a view of them, valid while `planes` is
// neither resized nor freed. `r`, `g`, `b`, `pixel_stride` and `row_stride` as above.
ColorView packed_rgb_to_color(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                              int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                              std::vector<std::uint8_t>& planes);

}  // namespace projtrack
