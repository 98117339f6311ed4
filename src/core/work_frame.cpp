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

// A row of 2×2 block means from two frame rows: the common case, in one pass.
void mean_2x2_row(const std::uint8_t* r0, const std::uint8_t* r1, int w, std::uint8_t* out) {
  for (int x = 0; x < w; ++x)
    out[x] =
        static_cast<std::uint8_t>((r0[2 * x] + r0[2 * x + 1] + r1[2 * x] + r1[2 * x + 1] + 2) >> 2);
}

// A row of means of s×s blocks (s <= 257) over frame columns [fx0, fx1) and rows [fy0, fy1):
// column sums first (contiguous adds, which the compiler vectorises; s rows of 255 fit in 16
// bits), then each block's columns (fewer than s in a last block the frame cuts), so the frame
// is still read once.
void mean_blocks_by_columns(const ImageView& luma, int s, int fx0, int fx1, int fy0, int fy1,
                            std::vector<std::uint16_t>& columns, int w, std::uint8_t* out) {
  const int span = fx1 - fx0;
  columns.assign(static_cast<std::size_t>(span), 0);
  std::uint16_t* col = columns.data();
  for (int fy = fy0; fy < fy1; ++fy) add_row(luma.row(fy) + fx0, col, span);
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
}

// The same for larger blocks, whose column sums would not fit in 16 bits: each frame row's blocks
// summed into `sums`, the first `full` of them whole.
void mean_blocks_by_rows(const ImageView& luma, int s, int fx0, int fx1, int fy0, int fy1, int full,
                         std::uint32_t* sums, int w, std::uint8_t* out) {
  std::fill(sums, sums + w, 0u);
  for (int fy = fy0; fy < fy1; ++fy) {
    const std::uint8_t* row = luma.row(fy) + fx0;
    for (int x = 0; x < full; ++x, row += s) {
      std::uint32_t sum = 0;
      for (int k = 0; k < s; ++k) sum += row[k];
      sums[x] += sum;
    }
    for (int x = full, fx = fx0 + full * s; fx < fx1; ++fx) sums[x] += luma.row(fy)[fx];
  }
  const int rows = fy1 - fy0;
  for (int x = 0; x < w; ++x) {
    const int bx0 = fx0 + x * s, count = (std::min(fx1, bx0 + s) - bx0) * rows;
    out[x] = static_cast<std::uint8_t>(count > 0 ? (sums[x] + count / 2) / count : 0);
  }
}

// The tables that read a value as the exposure `e` would have shown it: luma around the black
// level, chroma around its neutral 128.
void exposure_tables(const Exposure& e, std::array<std::uint8_t, 256>& luma,
                     std::array<std::uint8_t, 256>& chroma) {
  for (int v = 0; v < 256; ++v) {
    luma[v] = static_cast<std::uint8_t>(
        std::clamp<long>(std::lround(e.black + (v - e.black) * e.gain), 0, 255));
    chroma[v] =
        static_cast<std::uint8_t>(std::clamp<long>(std::lround(128 + (v - 128) * e.gain), 0, 255));
  }
}

// Every byte of p[0, n) read through `table`.
void apply_table(const std::array<std::uint8_t, 256>& table, std::uint8_t* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) p[i] = table[p[i]];
}

// The work pixels' luma in `rect` (work coordinates at scale s, within the frame): each the mean
// of its block.
void average_luma(const ImageView& frame, const Rect& rect, int s,
                  std::vector<std::uint16_t>& columns, std::uint32_t* sums, std::uint8_t* luma) {
  const int w = rect.width, h = rect.height, fw = frame.width, fh = frame.height;
  // Row sums of each block, then the mean: the frame is read once, row by row.
  const int fx0 = rect.x * s, fx1 = std::min(fw, (rect.x + w) * s);
  const int full = std::max(0, (fx1 - fx0) / s);  // blocks with all s columns in the frame
  for (int y = 0; y < h; ++y) {
    const int fy0 = (rect.y + y) * s, fy1 = std::min(fh, fy0 + s);
    std::uint8_t* out = luma + static_cast<std::size_t>(y) * w;
    if (s == 1)
      std::copy_n(frame.row(fy0) + fx0, w, out);
    else if (s == 2 && fy1 - fy0 == 2 && full == w)
      mean_2x2_row(frame.row(fy0) + fx0, frame.row(fy0 + 1) + fx0, w, out);
    else if (s <= 257)
      mean_blocks_by_columns(frame, s, fx0, fx1, fy0, fy1, columns, w, out);
    else
      mean_blocks_by_rows(frame, s, fx0, fx1, fy0, fy1, full, sums, w, out);
  }
}

// The chroma samples that cover frame pixels [f0, f1) of an axis subsampled by `shift`, and how
// many of those pixels each covers.
ChromaSpan samples_of(int f0, int f1, int shift) {
  ChromaSpan span;
  span.first = f0 >> shift;
  span.count = ((f1 - 1) >> shift) - span.first + 1;
  span.pixels = f1 - f0;
  span.inner = 1 << shift;
  span.first_weight = std::min(f1, (span.first + 1) << shift) - f0;
  span.last_weight = span.count == 1 ? span.first_weight : f1 - ((f1 - 1) >> shift << shift);
  return span;
}

int weight(const ChromaSpan& span, int k) {
  return k == 0 ? span.first_weight : k == span.count - 1 ? span.last_weight : span.inner;
}

// su[k] += w · u[k · stride] (and sv from v) for k < n: planar chroma (stride 1) in a loop the
// compiler vectorises.
PROJTRACK_VECTOR_CLONES void add_weighted(const std::uint8_t* u, const std::uint8_t* v, int stride,
                                          int n, std::uint32_t w, std::uint32_t* __restrict__ su,
                                          std::uint32_t* __restrict__ sv) {
  if (stride == 1) {
    for (int k = 0; k < n; ++k) su[k] += w * u[k];
    for (int k = 0; k < n; ++k) sv[k] += w * v[k];
    return;
  }
  for (int k = 0; k < n; ++k) {
    su[k] += w * u[static_cast<std::ptrdiff_t>(k) * stride];
    sv[k] += w * v[static_cast<std::ptrdiff_t>(k) * stride];
  }
}

// The work pixels' chroma in `rect`: each the mean over its block's pixels of the chroma sample
// that covers each, whatever the layout stores them at (I420's one per 2×2 pixels, YUY2's one per
// 2×1, Y444's and RGB's every pixel), so that every layout gives a block the same colour. A
// block's centre sample would read a YUY2 frame's chroma at other places than an I420 frame's,
// and full-resolution chroma (an RGB frame's) at one pixel where I420 has the mean of four; the
// samples' plain mean would weigh a sample half in an odd-sized block as much as one inside it.
void average_chroma(const ColorView& frame, const Rect& rect, int s, std::vector<ChromaSpan>& cols,
                    std::vector<std::uint32_t>& sums, std::uint8_t* u, std::uint8_t* v) {
  const int w = rect.width, h = rect.height;
  if (w <= 0 || h <= 0) return;
  const int fw = frame.luma.width, fh = frame.luma.height;
  const ChromaView& c = frame.chroma;
  if (s == 1 << c.shift_x && s == 1 << c.shift_y) {
    // One sample covers each block (4:2:0 at scale 2, 4:4:4 at scale 1; a block the frame's edge
    // cuts too): the mean is that sample.
    for (int y = 0; y < h; ++y) {
      const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(rect.y + y) * c.stride;
      for (int x = 0; x < w; ++x) {
        const std::ptrdiff_t i = row + static_cast<std::ptrdiff_t>(rect.x + x) * c.pixel_stride;
        u[static_cast<std::size_t>(y) * w + x] = c.u[i];
        v[static_cast<std::size_t>(y) * w + x] = c.v[i];
      }
    }
    return;
  }
  // The chroma columns of a row's blocks are the same on every row.
  cols.resize(static_cast<std::size_t>(w));
  for (int x = 0; x < w; ++x) {
    const int fx0 = (rect.x + x) * s;
    cols[x] = samples_of(fx0, std::min(fw, fx0 + s), c.shift_x);
  }
  // Each block row: the weighted sums down the chroma columns it covers (one pass over those
  // samples), then each block's weighted sum across its columns.
  const int c0 = cols[0].first, span = cols[w - 1].first + cols[w - 1].count - c0;
  sums.resize(2 * static_cast<std::size_t>(span));
  std::uint32_t* su = sums.data();
  std::uint32_t* sv = su + span;
  for (int y = 0; y < h; ++y) {
    const int fy0 = (rect.y + y) * s;
    const ChromaSpan rows = samples_of(fy0, std::min(fh, fy0 + s), c.shift_y);
    std::fill(su, su + 2 * span, 0u);
    for (int r = 0; r < rows.count; ++r) {
      const std::uint32_t wr = static_cast<std::uint32_t>(weight(rows, r));
      const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(rows.first + r) * c.stride +
                                static_cast<std::ptrdiff_t>(c0) * c.pixel_stride;
      add_weighted(c.u + at, c.v + at, c.pixel_stride, span, wr, su, sv);
    }
    std::uint8_t* uo = u + static_cast<std::size_t>(y) * w;
    std::uint8_t* vo = v + static_cast<std::size_t>(y) * w;
    for (int x = 0; x < w; ++x) {
      const ChromaSpan& col = cols[x];
      std::uint32_t bu = 0, bv = 0;
      for (int k = 0; k < col.count; ++k) {
        const std::uint32_t wc = static_cast<std::uint32_t>(weight(col, k));
        bu += wc * su[col.first - c0 + k];
        bv += wc * sv[col.first - c0 + k];
      }
      const std::uint32_t n = static_cast<std::uint32_t>(rows.pixels * col.pixels);
      uo[x] = static_cast<std::uint8_t>((bu + n / 2) / n);
      vo[x] = static_cast<std::uint8_t>((bv + n / 2) / n);
    }
  }
}

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
  average_luma(frame.luma, rect_, s, columns_, sums_.data(), luma);
  // A dim frame read as a brighter exposure would have shown it (ColorView::exposure).
  const Exposure& e = frame.exposure;
  if (!e.identity()) {
    exposure_tables(e, luma_lut_, chroma_lut_);
    apply_table(luma_lut_, luma, n);
  }
  view_.luma = ImageView(luma, w, h, w);
  if (!chroma) return;
  std::uint8_t* u = luma + n;
  std::uint8_t* v = u + n;
  average_chroma(frame, rect_, s, spans_, chroma_sums_, u, v);
  if (!e.identity()) apply_table(chroma_lut_, u, 2 * n);  // u, then v just after
  view_.chroma = {u, v, w, 1, 0, 0};
}

}  // namespace projtrack
