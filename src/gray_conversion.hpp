// Packed RGB of any component order to 8-bit gray, for frames that have no luma plane.
#pragma once

#include <cstddef>
#include <cstdint>

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

}  // namespace projtrack
