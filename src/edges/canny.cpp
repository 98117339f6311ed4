#include "edges/canny.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>

#include "core/vector_clones.hpp"
#include "projtrack/work_budget.hpp"

namespace projtrack {

namespace {

// The map is the output: edges 255, everything else 0 once the candidates are settled.
enum : std::uint8_t { kNot = 0, kMaybe = 1, kEdge = 255 };

// 3×3 Sobel of one row (rows above and below given, the border replicated) and its L1 norm, or 0
// where the norm is not above `low`: such a pixel is never an edge, and as a neighbour it loses
// every comparison to a pixel above `low` either way, so the suppression's answers are unchanged
// while runs of zeros can be skipped eight at a time.
// __restrict__ (kept by not inlining): the rows never overlap, so the compiler vectorises; on
// x86-64, once more for AVX2, chosen at load time when the CPU has it.
PROJTRACK_VECTOR_CLONES void gradient_row(const std::uint8_t* __restrict__ up,
                                          const std::uint8_t* __restrict__ mid,
                                          const std::uint8_t* __restrict__ down, int w,
                                          std::int16_t* __restrict__ dx,
                                          std::int16_t* __restrict__ dy,
                                          std::int16_t* __restrict__ mag, int low) {
  auto at = [w](const std::uint8_t* r, int x) { return int{r[std::clamp(x, 0, w - 1)]}; };
  auto edge = [&](int x) {
    const int gx = (at(up, x + 1) - at(up, x - 1)) + 2 * (at(mid, x + 1) - at(mid, x - 1)) +
                   (at(down, x + 1) - at(down, x - 1));
    const int gy = (at(down, x - 1) + 2 * at(down, x) + at(down, x + 1)) -
                   (at(up, x - 1) + 2 * at(up, x) + at(up, x + 1));
    dx[x] = static_cast<std::int16_t>(gx);
    dy[x] = static_cast<std::int16_t>(gy);
    const int norm = std::abs(gx) + std::abs(gy);
    mag[x] = static_cast<std::int16_t>(norm > low ? norm : 0);
  };
  edge(0);
  // The hot loop, in 16-bit lanes (every value fits: |gx|, |gy| <= 4 · 255), so the compiler
  // vectorises it eight or sixteen pixels at a time.
  const std::int16_t low16 = static_cast<std::int16_t>(std::clamp(low, -1, 4096));
  for (int x = 1; x < w - 1; ++x) {
    const std::int16_t gx = static_cast<std::int16_t>(
        (up[x + 1] - up[x - 1]) + 2 * (mid[x + 1] - mid[x - 1]) + (down[x + 1] - down[x - 1]));
    const std::int16_t gy = static_cast<std::int16_t>((down[x - 1] + 2 * down[x] + down[x + 1]) -
                                                      (up[x - 1] + 2 * up[x] + up[x + 1]));
    dx[x] = gx;
    dy[x] = gy;
    const std::int16_t norm = static_cast<std::int16_t>((gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy));
    mag[x] = norm > low16 ? norm : std::int16_t{0};
  }
  if (w > 1) edge(w - 1);
}

// What it costs (WorkBudget units): a pixel's gradient and a quiet stretch of the suppression
// are vectorised; a pixel above the low threshold takes the suppression's branches, which the
// processor mispredicts on textured content (noise costs many times a frame of smooth shading,
// as much as filling the frame several times over: tools/work_cost.cpp); a candidate's
// hysteresis pushes and pops.
constexpr std::uint64_t kCostPerStrongGradient = 12;
constexpr std::uint64_t kCostPerCandidate = 4;
constexpr int kRowsPerCheckpoint = 16;

// A threshold as a level of the integer L1 norm: floored, as cv::Canny does. L1 norms never
// exceed 8 · 255, so larger thresholds all mean "above every norm"; NaN and anything below -1 read
// as -1.
int gradient_level(double t) {
  return t >= -1.0 ? static_cast<int>(std::floor(std::min(t, 4096.0))) : -1;
}

// Gradients live in a ring of three rows (the row being suppressed and its two neighbours), so
// they stay in cache; only the map is frame-sized. Each row has one border pixel each side, of
// zero magnitude.
struct GradientRing {
  std::int16_t *dx, *dy, *mag;
  std::ptrdiff_t stride;

  // Where row y (-1 to h) lies in the ring, past its left border pixel.
  std::ptrdiff_t at(int y) const { return ((y + 3) % 3) * stride + 1; }
  // Row y of the image into the ring, or zeros outside the image.
  void compute(const ImageView& src, int y, int low) const {
    const int w = src.width, h = src.height;
    std::int16_t* m = mag + at(y);
    m[-1] = m[w] = 0;
    if (y < 0 || y >= h) {
      std::fill(m, m + w, 0);
      return;
    }
    gradient_row(src.row(std::max(y - 1, 0)), src.row(y), src.row(std::min(y + 1, h - 1)), w,
                 dx + at(y), dy + at(y), m, low);
  }
};

// Candidates of the hysteresis: map offsets of the strong edges (above `high`) still to extend,
// and of the weak ones (above `low` only).
struct Candidates {
  std::vector<std::int32_t>& strong;
  std::vector<std::int32_t>& weak;
};

// Non-maximum suppression of row y across the gradient's direction (one of four sectors; tan
// 22.5° in 15-bit fixed point), the same comparisons as OpenCV's, so ties resolve identically.
// Marks the row of the map (`map_row` is its offset, past the border pixel) and adds its peaks
// to the candidates; returns how many of its pixels are above `low`.
std::uint64_t suppress_row(const GradientRing& g, int y, int w, int low, int high,
                           std::uint8_t* map, std::ptrdiff_t map_row, Candidates& out) {
  constexpr int kShift = 15;
  constexpr int kTan22 = 13573;  // round(tan(22.5°) · 2^15)
  const std::int16_t* up = g.mag + g.at(y - 1);
  const std::int16_t* m = g.mag + g.at(y);
  const std::int16_t* down = g.mag + g.at(y + 1);
  const std::int16_t* gx = g.dx + g.at(y);
  const std::int16_t* gy = g.dy + g.at(y);
  std::uint8_t* row = map + map_row;
  row[-1] = row[w] = kNot;
  std::uint64_t strong = 0;
  for (int x = 0; x < w; ++x) {
    // Most pixels are far below `low` (stored as 0): skip eight at a time.
    if ((x & 7) == 0 && x + 8 <= w) {
      std::uint64_t a, b;
      std::memcpy(&a, m + x, 8);
      std::memcpy(&b, m + x + 4, 8);
      if ((a | b) == 0) {
        std::memset(row + x, kNot, 8);
        x += 7;
        continue;
      }
    }
    const int v = m[x];
    std::uint8_t mark = kNot;
    if (v > low) {
      ++strong;
      const int ax = std::abs(int{gx[x]}), ay = std::abs(int{gy[x]}) << kShift;
      const int tg22 = ax * kTan22;
      bool peak;
      if (ay < tg22) {
        peak = v > m[x - 1] && v >= m[x + 1];
      } else if (ay > tg22 + (ax << (kShift + 1))) {
        peak = v > up[x] && v >= down[x];
      } else {
        const int s = (gx[x] ^ gy[x]) < 0 ? -1 : 1;
        peak = v > up[x - s] && v > down[x + s];
      }
      if (peak) {
        const std::int32_t at = static_cast<std::int32_t>(map_row + x);
        mark = v > high ? kEdge : kMaybe;
        (mark == kEdge ? out.strong : out.weak).push_back(at);
      }
    }
    row[x] = mark;
  }
  return strong;
}

// What `rows` rows of width w cost, `strong` of their pixels above the low threshold.
std::uint64_t rows_cost(int rows, int w, std::uint64_t strong) {
  return static_cast<std::uint64_t>(rows) * w / kScannedPixelsPerCost +
         strong * kCostPerStrongGradient;
}

// Every row of the map (of row stride ms, with its border rows) marked by the suppression. With a
// budget, the rows' work is spent every kRowsPerCheckpoint rows; once it runs out, the rows left
// are "not an edge" and the answer is false: the map is incomplete.
bool suppress_non_maxima(const ImageView& src, int low, int high, const GradientRing& ring,
                         std::uint8_t* map, std::ptrdiff_t ms, Candidates& out,
                         WorkBudget* budget) {
  const int w = src.width, h = src.height;
  std::memset(map, kNot, ms);
  std::memset(map + ms * (h + 1), kNot, ms);
  ring.compute(src, -1, low);
  ring.compute(src, 0, low);
  std::uint64_t strong = 0;  // pixels above `low` since the last checkpoint
  for (int y = 0; y < h; ++y) {
    if (budget && y % kRowsPerCheckpoint == 0) {
      budget->spend(rows_cost(std::min(y, kRowsPerCheckpoint), w, strong));
      strong = 0;
      if (budget->exhausted()) {
        for (int r = y; r < h; ++r) std::memset(map + ms * (r + 1), kNot, ms);
        return false;
      }
    }
    ring.compute(src, y + 1, low);
    strong += suppress_row(ring, y, w, low, high, map, ms * (y + 1) + 1, out);
  }
  if (budget) {  // the rows since the last checkpoint
    const int last_rows = h % kRowsPerCheckpoint == 0 ? kRowsPerCheckpoint : h % kRowsPerCheckpoint;
    budget->spend(rows_cost(last_rows, w, strong));
  }
  return true;
}

// Hysteresis: every candidate 8-connected to a strong edge becomes an edge (depth first from the
// strong ones, `out.strong` is emptied); the other weak ones are not edges.
void hysteresis(std::uint8_t* map, std::ptrdiff_t ms, Candidates& out) {
  const std::ptrdiff_t around[8] = {-1, 1, -ms - 1, -ms, -ms + 1, ms - 1, ms, ms + 1};
  std::vector<std::int32_t>& stack = out.strong;
  while (!stack.empty()) {
    const std::ptrdiff_t p = stack.back();
    stack.pop_back();
    for (std::ptrdiff_t d : around) {
      if (map[p + d] == kMaybe) {
        map[p + d] = kEdge;
        stack.push_back(static_cast<std::int32_t>(p + d));
      }
    }
  }
  for (const std::int32_t p : out.weak)
    if (map[p] == kMaybe) map[p] = kNot;
}

}  // namespace

ImageView CannyDetector::detect(const ImageView& src, double low_threshold, double high_threshold,
                                WorkBudget* budget) {
  const int w = src.width, h = src.height;
  if (!src.valid()) return {};
  if (low_threshold > high_threshold) std::swap(low_threshold, high_threshold);
  // Offsets into the map are 32-bit: refuse what would not fit (over 2^31 pixels).
  if ((static_cast<double>(w) + 2) * (static_cast<double>(h) + 2) > 2147483647.0) return {};
  const int low = gradient_level(low_threshold), high = gradient_level(high_threshold);

  // Rows of the ring and of the map have one border pixel each side: a zero magnitude, and "not
  // an edge".
  const std::ptrdiff_t ms = w + 2;
  if (mag_.size() < static_cast<std::size_t>(3 * ms)) {
    mag_.resize(3 * ms);
    dx_.resize(3 * ms);
    dy_.resize(3 * ms);
  }
  const std::size_t nb = static_cast<std::size_t>(ms) * (h + 2);
  if (map_.size() < nb) map_.resize(nb);
  std::uint8_t* map = map_.data();
  const GradientRing ring{dx_.data(), dy_.data(), mag_.data(), ms};
  stack_.clear();
  maybes_.clear();
  Candidates candidates{stack_, maybes_};

  bool complete = suppress_non_maxima(src, low, high, ring, map, ms, candidates, budget);
  if (budget && complete) {  // the hysteresis, done only if it can be paid
    const std::uint64_t hysteresis_cost = (stack_.size() + maybes_.size()) * kCostPerCandidate;
    complete = !budget->exhausted(hysteresis_cost);
    if (complete) budget->spend(hysteresis_cost);
  }
  if (!complete) stack_.clear();  // an incomplete map: the weak candidates are dropped below
  hysteresis(map, ms, candidates);
  return ImageView(map + ms + 1, w, h, ms);
}

}  // namespace projtrack
