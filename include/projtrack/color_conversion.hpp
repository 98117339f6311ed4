// Packed RGB of any component order to the luma and chroma the tracker reads, for frames that
// have no YUV planes; full-range gray or YUV to that same video range; packed YUV's luma into a
// plane. packed_rgb_to_color() is the entry point for an RGB frame (the element's RGB caps,
// Python's BGR arrays) and full_to_video_range() for a full-range one (GRAY8, a JPEG decoder's
// YUV, Python's gray arrays); the functions they call are here for what reads a part.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "color_view.hpp"

namespace projtrack {

// The gray of one RGB pixel, (77·R + 150·G + 29·B + 128) / 256: BT.601's weights, full range
// (0–255), as a GRAY8 frame stores it.
constexpr std::uint8_t gray_of(int r, int g, int b) {
  return static_cast<std::uint8_t>((77 * r + 150 * g + 29 * b + 128) >> 8);
}

// The luma of one RGB pixel at video range (BT.601 studio swing: 16–235), as a camera's or a
// decoder's I420 stores it (ColorView: the one range the tracker reads).
constexpr std::uint8_t luma_of(int r, int g, int b) {
  return static_cast<std::uint8_t>(((66 * r + 129 * g + 25 * b + 128) >> 8) + 16);
}

// luma_of() of every pixel. `r`, `g`, `b` point at the first pixel's components; `pixel_stride`
// is 3 or 4 bytes; rows of both images may be padded.
void packed_rgb_to_luma(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                        int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                        std::uint8_t* luma, std::ptrdiff_t luma_stride);

// One component of a packed format (YUY2's or UYVY's luma: every second byte) into a plane of
// its own; rows of both images may be padded (and run bottom-up: a negative `row_stride`). The
// images must not overlap. Pixel strides 1 and 2 are vectorised.
void gather_component(const std::uint8_t* first, int pixel_stride, std::ptrdiff_t row_stride,
                      int width, int height, std::uint8_t* out, std::ptrdiff_t out_stride);

// The chroma of one RGB pixel, BT.601 at video range (16–240): Cb = U and Cr = V, 128 for a
// neutral colour.
constexpr std::uint8_t u_of(int r, int g, int b) {
  return static_cast<std::uint8_t>(((-38 * r - 74 * g + 112 * b + 128) >> 8) + 128);
}
constexpr std::uint8_t v_of(int r, int g, int b) {
  return static_cast<std::uint8_t>(((112 * r - 94 * g - 18 * b + 128) >> 8) + 128);
}
// u_of() and v_of() of the sums of four pixels' components: the chroma of their mean colour.
constexpr std::uint8_t u_of_sums(int r4, int g4, int b4) {
  return static_cast<std::uint8_t>(((-38 * r4 - 74 * g4 + 112 * b4 + 512) >> 10) + 128);
}
constexpr std::uint8_t v_of_sums(int r4, int g4, int b4) {
  return static_cast<std::uint8_t>(((112 * r4 - 94 * g4 - 18 * b4 + 512) >> 10) + 128);
}

// The chroma at half resolution, as I420 stores it: of the mean colour of every 2×2 block (a
// last odd row or column: of its pixels), into planes of (width + 1) / 2 × (height + 1) / 2 with
// row stride `chroma_stride`.
void packed_rgb_to_chroma(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                          int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                          std::uint8_t* u, std::uint8_t* v, std::ptrdiff_t chroma_stride);

// A packed RGB frame as the tracker reads it: its luma (packed_rgb_to_luma) and half-resolution
// chroma (packed_rgb_to_chroma) written into `planes` (resized to fit; reused from frame to
// frame, it allocates only when the frame grows), and a view of them, valid while `planes` is
// neither resized nor freed. `r`, `g`, `b`, `pixel_stride` and `row_stride` as above.
ColorView packed_rgb_to_color(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                              int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                              std::vector<std::uint8_t>& planes);

// A full-range frame (luma 0–255, chroma 1–255 about 128: GRAY8, JPEG's YUV, OpenCV's gray) at
// the video range the tracker reads (luma 16–235, chroma 16–240), its values mapped linearly
// and rounded: its luma, and its chroma (if any) at the same subsampling, copied into `planes`
// (as packed_rgb_to_color()'s) and viewed there. The exposure is carried over.
ColorView full_to_video_range(const ColorView& full, std::vector<std::uint8_t>& planes);

}  // namespace projtrack
