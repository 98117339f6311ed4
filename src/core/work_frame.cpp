#include "core/work_frame.hpp"

#include <algorithm>
#include <cmath>

#include "core/vector_clones.hpp"

namespace projtrack {

namespace {

// col[i] += row[i] over a block row's frame columns.
PROJTRACK_VECTOR_CLONES void add_row(const std::uint8_t* __restrict__ row,
                                     std::uint16_t* __restrict__ col, int n) {
  for (int i = 0; i < n; ++i) col[i] = static_cast<std::uint16_t>(col[i] + row[i]);
}

// round(n / d) for a mean of bytes (n <= 255 d) and 0 < d < 2^17, by a multiplication: exact,
// since the reciprocal's error, under n / 2^42, stays below 1 / d (checked for every such d), and
// n·m stays under 2^51.
class RoundedDivision {
 public:
  explicit RoundedDivision(std::uint32_t d) : d_(d), m_(((std::uint64_t{1} << 42) + d - 1) / d) {}
  std::uint32_t operator()(std::uint32_t n) const {
    return static_cast<std::uint32_t>(((n + d_ / 2) * m_) >> 42);
  }

 private:
  std::uint64_t d_, m_;
};

int floor_div(long long a, int b) { return static_cast<int>(a >= 0 ? a / b : -((-a + b - 1) / b)); }

}  // namespace

int work_scale(double pixels, double target) {
  if (!(pixels > 0) || !(target > 0)) return 1;
  return std::max(1, static_cast<int>(std::lround(std::sqrt(pixels / target))));
}

Rect to_work(const Rect& r, int scale) {
  const int s = std::max(1, scale);
  const int x0 = floor_div(r.x, s), y0 = floor_div(r.y, s);
  const int x1 = floor_div(static_cast<long long>(r.x) + r.width + s - 1, s);
  const int y1 = floor_div(static_cast<long long>(r.y) + r.height + s - 1, s);
  return {x0, y0, x1 - x0, y1 - y0};
}

Rect to_frame(const Rect& r, int scale, int width, int height) {
  const long long s = std::max(1, scale);
  const auto clamp_int = [](long long v) {
    return static_cast<int>(std::clamp<long long>(v, -(1LL << 30), 1LL << 30));
  };
  return clip_to_frame(
      {clamp_int(r.x * s), clamp_int(r.y * s), clamp_int(r.width * s), clamp_int(r.height * s)},
      width, height);
}

void WorkFrame::build(const ColorView& frame, int scale, const Rect& region) {
  scale_ = std::max(1, scale);
  const int s = scale_, fw = frame.luma.width, fh = frame.luma.height;
  rect_ = region & Rect{0, 0, (fw + s - 1) / s, (fh + s - 1) / s};
  const int w = rect_.width, h = rect_.height;
  const std::size_t n = static_cast<std::size_t>(std::max(0, w)) * std::max(0, h);
  const bool chroma = frame.has_chroma();
  planes_.resize(n * (chroma ? 3 : 1));
  sums_.resize(static_cast<std::size_t>(std::max(0, w)));
  view_ = {};
  if (n == 0) return;
  std::uint8_t* luma = planes_.data();
  std::uint32_t* sums = sums_.data();
  // Row sums of each block, then the mean: the frame is read once, row by row.
  const int fx0 = rect_.x * s, fx1 = std::min(fw, (rect_.x + w) * s);
  const int full = std::max(0, (fx1 - fx0) / s);  // blocks with all s columns in the frame
  for (int y = 0; y < h; ++y) {
    const int fy0 = (rect_.y + y) * s, fy1 = std::min(fh, fy0 + s);
    std::uint8_t* out = luma + static_cast<std::size_t>(y) * w;
    if (s == 1) {
      std::copy_n(frame.luma.row(fy0) + fx0, w, out);
      continue;
    }
    if (s == 2 && fy1 - fy0 == 2 && full == w) {  // the common case, in one pass
      const std::uint8_t* r0 = frame.luma.row(fy0) + fx0;
      const std::uint8_t* r1 = frame.luma.row(fy0 + 1) + fx0;
      for (int x = 0; x < w; ++x)
        out[x] = static_cast<std::uint8_t>(
            (r0[2 * x] + r0[2 * x + 1] + r1[2 * x] + r1[2 * x + 1] + 2) >> 2);
      continue;
    }
    if (s <= 257) {
      // Column sums first (contiguous adds, which the compiler vectorises; s rows of 255 fit in
      // 16 bits), then each block's columns (fewer than s in a last block the frame cuts): the
      // frame is still read once.
      const int span = fx1 - fx0;
      columns_.assign(static_cast<std::size_t>(span), 0);
      std::uint16_t* col = columns_.data();
      for (int fy = fy0; fy < fy1; ++fy) add_row(frame.luma.row(fy) + fx0, col, span);
      // A whole block's mean by a multiplication (a division per block cost more than the sums).
      const int rows = fy1 - fy0;
      const RoundedDivision whole(static_cast<std::uint32_t>(s * rows));
      for (int x = 0; x < w; ++x) {
        const int c0 = x * s, c1 = std::min(span, c0 + s);
        std::uint32_t sum = 0;
        for (int k = c0; k < c1; ++k) sum += col[k];
        const std::uint32_t count = static_cast<std::uint32_t>(std::max(0, c1 - c0) * rows);
        out[x] = static_cast<std::uint8_t>(c1 - c0 == s ? whole(sum)
                                           : count > 0  ? (sum + count / 2) / count
                                                        : 0);
      }
      continue;
    }
    std::fill(sums, sums + w, 0u);
    for (int fy = fy0; fy < fy1; ++fy) {
      const std::uint8_t* row = frame.luma.row(fy) + fx0;
      for (int x = 0; x < full; ++x, row += s) {
        std::uint32_t sum = 0;
        for (int k = 0; k < s; ++k) sum += row[k];
        sums[x] += sum;
      }
      for (int x = full, fx = fx0 + full * s; fx < fx1; ++fx) sums[x] += frame.luma.row(fy)[fx];
    }
    const int rows = fy1 - fy0;
    for (int x = 0; x < w; ++x) {
      const int bx0 = fx0 + x * s, count = (std::min(fx1, bx0 + s) - bx0) * rows;
      out[x] = static_cast<std::uint8_t>(count > 0 ? (sums[x] + count / 2) / count : 0);
    }
  }
  // A dim frame read as a brighter exposure would have shown it (ColorView::exposure).
  const Exposure& e = frame.exposure;
  if (!e.identity()) {
    for (int v = 0; v < 256; ++v) {
      luma_lut_[v] = static_cast<std::uint8_t>(
          std::clamp<long>(std::lround(e.black + (v - e.black) * e.gain), 0, 255));
      chroma_lut_[v] = static_cast<std::uint8_t>(
          std::clamp<long>(std::lround(128 + (v - 128) * e.gain), 0, 255));
    }
    for (std::size_t i = 0; i < n; ++i) luma[i] = luma_lut_[luma[i]];
  }
  view_.luma = ImageView(luma, w, h, w);
  if (!chroma) return;
  std::uint8_t* u = luma + n;
  std::uint8_t* v = u + n;
  // Each block's centre sample: the chroma offsets of a row's blocks are the same on every row.
  const ChromaView& c = frame.chroma;
  offsets_.resize(static_cast<std::size_t>(w));
  for (int x = 0; x < w; ++x) {
    const int cx = std::min(fw - 1, (rect_.x + x) * s + s / 2);
    offsets_[x] = static_cast<std::ptrdiff_t>(cx >> c.shift_x) * c.pixel_stride;
  }
  for (int y = 0; y < h; ++y) {
    const int cy = std::min(fh - 1, (rect_.y + y) * s + s / 2);
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(cy >> c.shift_y) * c.stride;
    std::uint8_t* uo = u + static_cast<std::size_t>(y) * w;
    std::uint8_t* vo = v + static_cast<std::size_t>(y) * w;
    for (int x = 0; x < w; ++x) {
      uo[x] = c.u[row + offsets_[x]];
      vo[x] = c.v[row + offsets_[x]];
    }
  }
  if (!e.identity())
    for (std::size_t i = 0; i < 2 * n; ++i) u[i] = chroma_lut_[u[i]];  // u, then v just after
  view_.chroma = {u, v, w, 1, 0, 0};
}

}  // namespace projtrack
