#include "canny.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>

namespace projtrack {

namespace {

enum : std::uint8_t { kMaybe = 0, kNot = 1, kEdge = 2 };

// 3×3 Sobel of one row (rows above and below given, the border replicated) and its L1 norm.
// __restrict__ (kept by not inlining): the rows never overlap, so the compiler vectorises.
[[gnu::noinline]] void gradient_row(const std::uint8_t* __restrict__ up,
                                    const std::uint8_t* __restrict__ mid,
                                    const std::uint8_t* __restrict__ down, int w,
                                    std::int16_t* __restrict__ dx, std::int16_t* __restrict__ dy,
                                    std::int16_t* __restrict__ mag) {
  auto at = [w](const std::uint8_t* r, int x) { return int{r[std::clamp(x, 0, w - 1)]}; };
  auto edge = [&](int x) {
    const int gx = (at(up, x + 1) - at(up, x - 1)) + 2 * (at(mid, x + 1) - at(mid, x - 1)) +
                   (at(down, x + 1) - at(down, x - 1));
    const int gy = (at(down, x - 1) + 2 * at(down, x) + at(down, x + 1)) -
                   (at(up, x - 1) + 2 * at(up, x) + at(up, x + 1));
    dx[x] = static_cast<std::int16_t>(gx);
    dy[x] = static_cast<std::int16_t>(gy);
    mag[x] = static_cast<std::int16_t>(std::abs(gx) + std::abs(gy));
  };
  edge(0);
  for (int x = 1; x < w - 1; ++x) {  // the hot loop: branch-free, vectorised
    const int gx =
        (up[x + 1] - up[x - 1]) + 2 * (mid[x + 1] - mid[x - 1]) + (down[x + 1] - down[x - 1]);
    const int gy = (down[x - 1] + 2 * down[x] + down[x + 1]) - (up[x - 1] + 2 * up[x] + up[x + 1]);
    dx[x] = static_cast<std::int16_t>(gx);
    dy[x] = static_cast<std::int16_t>(gy);
    mag[x] = static_cast<std::int16_t>(std::abs(gx) + std::abs(gy));
  }
  if (w > 1) edge(w - 1);
}

}  // namespace

void CannyDetector::detect(const ImageView& src, double low_threshold, double high_threshold,
                           std::uint8_t* dst, std::ptrdiff_t dst_stride) {
  const int w = src.width, h = src.height;
  if (!src.valid()) return;
  if (low_threshold > high_threshold) std::swap(low_threshold, high_threshold);
  // L1 norms never exceed 8 · 255, so larger thresholds all mean "above every norm".
  const int low = static_cast<int>(std::floor(std::clamp(low_threshold, -1.0, 4096.0)));
  const int high = static_cast<int>(std::floor(std::clamp(high_threshold, -1.0, 4096.0)));

  const std::ptrdiff_t ms = w + 2;  // mag_ and map_ rows: one border pixel each side
  const std::size_t n = static_cast<std::size_t>(w) * h,
                    nb = static_cast<std::size_t>(ms) * (h + 2);
  if (dx_.size() < n) dx_.resize(n), dy_.resize(n);
  if (mag_.size() < nb) mag_.resize(nb), map_.resize(nb);

  std::fill(mag_.begin(), mag_.begin() + ms, 0);
  std::fill(mag_.begin() + ms * (h + 1), mag_.begin() + ms * (h + 2), 0);
  for (int y = 0; y < h; ++y) {
    std::int16_t* m = mag_.data() + ms * (y + 1);
    m[0] = m[w + 1] = 0;
    gradient_row(src.row(std::max(y - 1, 0)), src.row(y), src.row(std::min(y + 1, h - 1)), w,
                 dx_.data() + static_cast<std::ptrdiff_t>(y) * w,
                 dy_.data() + static_cast<std::ptrdiff_t>(y) * w, m + 1);
  }

  // Non-maximum suppression across the gradient's direction (one of four sectors; tan 22.5° in
  // 15-bit fixed point), the same comparisons as OpenCV's, so ties resolve identically.
  constexpr int kShift = 15;
  constexpr int kTan22 = 13573;  // round(tan(22.5°) · 2^15)
  std::uint8_t* map = map_.data();
  std::fill(map, map + ms, kNot);
  std::fill(map + ms * (h + 1), map + ms * (h + 2), kNot);
  stack_.clear();
  for (int y = 0; y < h; ++y) {
    const std::int16_t* m = mag_.data() + ms * (y + 1) + 1;
    const std::int16_t* gx = dx_.data() + static_cast<std::ptrdiff_t>(y) * w;
    const std::int16_t* gy = dy_.data() + static_cast<std::ptrdiff_t>(y) * w;
    std::uint8_t* row = map + ms * (y + 1) + 1;
    row[-1] = row[w] = kNot;
    for (int x = 0; x < w; ++x) {
      // Most pixels are far below `low`: skip eight at a time (an OR the compiler vectorises).
      if ((x & 7) == 0 && x + 8 <= w) {
        bool any = false;
        for (int k = 0; k < 8; ++k) any |= m[x + k] > low;
        if (!any) {
          std::fill(row + x, row + x + 8, kNot);
          x += 7;
          continue;
        }
      }
      const int v = m[x];
      std::uint8_t mark = kNot;
      if (v > low) {
        const int ax = std::abs(int{gx[x]}), ay = std::abs(int{gy[x]}) << kShift;
        const int tg22 = ax * kTan22;
        bool peak;
        if (ay < tg22) {
          peak = v > m[x - 1] && v >= m[x + 1];
        } else if (ay > tg22 + (ax << (kShift + 1))) {
          peak = v > m[x - ms] && v >= m[x + ms];
        } else {
          const int s = (gx[x] ^ gy[x]) < 0 ? -1 : 1;
          peak = v > m[x - ms - s] && v > m[x + ms + s];
        }
        if (peak) {
          mark = v > high ? kEdge : kMaybe;
          if (mark == kEdge) stack_.push_back(static_cast<std::int32_t>(ms * (y + 1) + 1 + x));
        }
      }
      row[x] = mark;
    }
  }

  // Hysteresis: every candidate 8-connected to an edge is an edge.
  const std::ptrdiff_t around[8] = {-1, 1, -ms - 1, -ms, -ms + 1, ms - 1, ms, ms + 1};
  while (!stack_.empty()) {
    const std::ptrdiff_t p = stack_.back();
    stack_.pop_back();
    for (std::ptrdiff_t d : around) {
      if (map[p + d] == kMaybe) {
        map[p + d] = kEdge;
        stack_.push_back(static_cast<std::int32_t>(p + d));
      }
    }
  }

  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = map + ms * (y + 1) + 1;
    std::uint8_t* out = dst + static_cast<std::ptrdiff_t>(y) * dst_stride;
    for (int x = 0; x < w; ++x) out[x] = row[x] == kEdge ? 255 : 0;
  }
}

}  // namespace projtrack
