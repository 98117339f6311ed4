#include "edges/box_blur.hpp"

#include <algorithm>
#include <cstddef>

#include "core/vector_clones.hpp"

namespace projtrack {

namespace {

// round(sum / 9) = floor((2 sum + 9) / 18) for sum <= 9 * 255, as a multiply and a shift (exact
// in that range: the error stays under 1/128, and the fraction of x / 18 under 17/18), which the
// compiler vectorises where it would not vectorise a division.
inline std::uint8_t div9(std::uint16_t sum) {
  const std::uint16_t x = static_cast<std::uint16_t>(sum * 2 + 9);
  return static_cast<std::uint8_t>((std::uint32_t{x} * 3641u) >> 16);
}

}  // namespace

PROJTRACK_VECTOR_CLONES void box_blur3(const ImageView& src, const Rect& region, std::uint8_t* dst,
                                       std::ptrdiff_t dst_stride) {
  const int w = region.width, x0 = region.x, W = src.width;
  if (w <= 0 || region.height <= 0) return;
  // Column sums of the three rows for x0 - 1 .. x0 + w, then the horizontal sum of three.
  // A fixed stack of 4096 + 2 columns at a time keeps this free of allocation.
  constexpr int kChunk = 4096;
  std::uint16_t col[kChunk + 2];
  for (int y = 0; y < region.height; ++y) {
    const int sy = region.y + y;
    const std::uint8_t* up = src.row(std::max(sy - 1, 0));
    const std::uint8_t* mid = src.row(sy);
    const std::uint8_t* down = src.row(std::min(sy + 1, src.height - 1));
    std::uint8_t* out = dst + static_cast<std::ptrdiff_t>(y) * dst_stride;
    for (int c0 = 0; c0 < w; c0 += kChunk) {
      const int n = std::min(kChunk, w - c0);
      const int first = x0 + c0 - 1;  // the column left of the chunk
      const int lo = std::max(first, 0), hi = std::min(first + n + 2, W);  // [lo, hi) inside
      for (int x = lo; x < hi; ++x) col[x - first] = up[x] + mid[x] + down[x];
      if (first < 0) col[0] = col[1];                           // replicate the left border
      if (first + n + 1 >= W) col[n + 1] = col[W - 1 - first];  // and the right one
      for (int i = 0; i < n; ++i) out[c0 + i] = div9(col[i] + col[i + 1] + col[i + 2]);
    }
  }
}

}  // namespace projtrack
