#include "core/mask.hpp"

#include <algorithm>
#include <cmath>

#include "core/byte_words.hpp"
#include "core/vector_clones.hpp"

namespace projtrack {

void Mask::reset(const Rect& r) {
  rect_ = r.empty() ? Rect{} : r;
  const std::size_t n = static_cast<std::size_t>(rect_.width) * rect_.height;
  if (data_.size() < n) data_.resize(n);
  std::fill_n(data_.begin(), n, 0);
}

void Mask::crop() {
  BoundsAccumulator bounds;
  for (int y = 0; y < rect_.height; ++y) {
    const std::uint8_t* r = row(y);
    int first = -1, last = -1;
    for (int x = 0; x < rect_.width; ++x) {
      if (!r[x]) continue;
      if (first < 0) first = x;
      last = x;
    }
    if (first >= 0) bounds.add_run(first, last, y);
  }
  const Rect b = bounds.rect();
  if (b.empty()) {
    rect_ = {};
    return;
  }
  // Rows move up and left in place: each destination precedes its source.
  for (int y = 0; y < b.height; ++y)
    std::copy_n(data_.data() + static_cast<std::size_t>(y + b.y) * rect_.width + b.x, b.width,
                data_.data() + static_cast<std::size_t>(y) * b.width);
  rect_ = {rect_.x + b.x, rect_.y + b.y, b.width, b.height};
}

namespace {

// The first x in [from, w) whose pixel is set (`set`) or unset (!`set`), or w; eight pixels at a
// time through the stretches without one.
int next_run(const std::uint8_t* row, int from, int w, bool set) {
  constexpr std::uint64_t kHigh = 0x8080808080808080ull;
  int x = from;
  for (; x + 8 <= w; x += 8) {
    const std::uint64_t bytes = nonzero_bytes(load8(row + x));
    const std::uint64_t hits = set ? bytes : bytes ^ kHigh;
    if (hits) return x + first_byte(hits);
  }
  for (; x < w; ++x)
    if ((row[x] != 0) == set) return x;
  return w;
}

}  // namespace

MaskMoments moments(const Mask& m) {
  MaskMoments out;
  const Rect& r = m.rect();
  double sx = 0, sy = 0;
  std::size_t n = 0;
  BoundsAccumulator bounds;
  for (int y = 0; y < r.height; ++y) {
    const std::uint8_t* row = m.row(y);
    // Run by run: a run [a, b) adds b - a pixels and the sum of a .. b - 1.
    std::size_t row_n = 0, row_sx = 0;
    int first = -1, last = -1;
    for (int a = next_run(row, 0, r.width, true); a < r.width;) {
      const int b = next_run(row, a, r.width, false);
      row_n += static_cast<std::size_t>(b - a);
      row_sx += (static_cast<std::size_t>(a) + b - 1) * static_cast<std::size_t>(b - a) / 2;
      if (first < 0) first = a;
      last = b - 1;
      a = next_run(row, b, r.width, true);
    }
    if (!row_n) continue;
    n += row_n;
    sx += static_cast<double>(row_sx) + static_cast<double>(row_n) * r.x;
    sy += static_cast<double>(row_n) * (y + r.y);
    bounds.add_run(first + r.x, last + r.x, y + r.y);
  }
  if (!n) return out;
  out.area = static_cast<double>(n);
  out.centroid = {sx / n, sy / n};
  out.bbox = bounds.rect();
  return out;
}

void embed(const Mask& src, const Rect& r, Mask& dst) {
  dst.reset(r);
  const Rect common = src.rect() & r;
  for (int y = common.y; y < common.bottom(); ++y)
    std::copy_n(src.row(y - src.rect().y) + (common.x - src.rect().x), common.width,
                dst.row(y - r.y) + (common.x - r.x));
}

void rescale(const Mask& src, int from, int to, Mask& dst) {
  from = std::max(1, from);
  to = std::max(1, to);
  const Rect& r = src.rect();
  const auto down = [](long long v, int d) { return v >= 0 ? v / d : -((-v + d - 1) / d); };
  const int x0 = static_cast<int>(down(1LL * r.x * from, to));
  const int y0 = static_cast<int>(down(1LL * r.y * from, to));
  const int x1 = static_cast<int>(down(1LL * r.right() * from + to - 1, to));
  const int y1 = static_cast<int>(down(1LL * r.bottom() * from + to - 1, to));
  dst.reset({x0, y0, x1 - x0, y1 - y0});
  for (int y = y0; y < y1; ++y) {
    const int sy = static_cast<int>(down(1LL * y * to + to / 2, from));
    std::uint8_t* d = dst.row(y - y0);
    for (int x = x0; x < x1; ++x)
      d[x - x0] = src.at({static_cast<int>(down(1LL * x * to + to / 2, from)), sy});
  }
}

void resample(const Mask& src, int from, double sx, double sy, int to, Mask& dst) {
  from = std::max(1, from);
  to = std::max(1, to);
  if (!(sx > 0 && sy > 0 && std::isfinite(sx) && std::isfinite(sy)) || src.empty()) {
    dst.reset({});
    return;
  }
  // Work pixel v at scale s covers frame pixels [v·s, (v+1)·s).
  const Rect& r = src.rect();
  const double kx = sx * from / to, ky = sy * from / to;  // src work px → dst work px
  const auto to_int = [](double v) { return static_cast<int>(std::clamp(v, -1e9, 1e9)); };
  const int x0 = to_int(std::floor(r.x * kx)), y0 = to_int(std::floor(r.y * ky));
  const int x1 = to_int(std::ceil(r.right() * kx)), y1 = to_int(std::ceil(r.bottom() * ky));
  dst.reset({x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)});
  for (int y = dst.rect().y; y < dst.rect().bottom(); ++y) {
    const int from_y = static_cast<int>(std::floor((y + 0.5) / ky));
    std::uint8_t* d = dst.row(y - dst.rect().y);
    for (int x = dst.rect().x; x < dst.rect().right(); ++x)
      d[x - dst.rect().x] = src.at({static_cast<int>(std::floor((x + 0.5) / kx)), from_y});
  }
}

void MaskOps::flood(Mask& m, Point2i p, std::uint8_t value, std::uint8_t mark) {
  const int w = m.rect().width, h = m.rect().height;
  stack_.clear();
  stack_.push_back(p);
  while (!stack_.empty()) {
    const Point2i s = stack_.back();
    stack_.pop_back();
    std::uint8_t* row = m.row(s.y);
    if (row[s.x] != value) continue;
    int x0 = s.x, x1 = s.x;
    while (x0 > 0 && row[x0 - 1] == value) --x0;
    while (x1 < w - 1 && row[x1 + 1] == value) ++x1;
    std::fill(row + x0, row + x1 + 1, mark);
    for (int ny = s.y - 1; ny <= s.y + 1; ny += 2) {
      if (ny < 0 || ny >= h) continue;
      const std::uint8_t* nrow = m.row(ny);
      bool in_run = false;
      for (int x = x0; x <= x1; ++x) {
        const bool open = nrow[x] == value;
        if (open && !in_run) stack_.push_back({x, ny});
        in_run = open;
      }
    }
  }
}

void MaskOps::fill_holes(Mask& m) {
  const int w = m.rect().width, h = m.rect().height;
  if (w == 0 || h == 0) return;
  for (int x = 0; x < w; ++x) {
    if (m.row(0)[x] == 0) flood(m, {x, 0}, 0, 2);
    if (m.row(h - 1)[x] == 0) flood(m, {x, h - 1}, 0, 2);
  }
  for (int y = 0; y < h; ++y) {
    if (m.row(y)[0] == 0) flood(m, {0, y}, 0, 2);
    if (m.row(y)[w - 1] == 0) flood(m, {w - 1, y}, 0, 2);
  }
  for (int y = 0; y < h; ++y) {
    std::uint8_t* row = m.row(y);
    for (int x = 0; x < w; ++x) row[x] = row[x] != 2;  // outside → 0, holes and object → 1
  }
}

bool MaskOps::keep_component(Mask& m, Point2i p) {
  if (!m.at(p)) return false;
  flood(m, {p.x - m.rect().x, p.y - m.rect().y}, 1, 2);
  for (int y = 0; y < m.rect().height; ++y) {
    std::uint8_t* row = m.row(y);
    for (int x = 0; x < m.rect().width; ++x) row[x] = row[x] == 2;
  }
  return true;
}

// Chebyshev dilation by r (or, with `invert`, the same of the unset pixels and everything outside
// the mask, which is the complement of the erosion): along each row, then each column, a pixel
// is reached when the nearest seed in that direction lies within r.
namespace {

// One row of a column pass: d (per column, the rows since the last reached one, saturated at
// cap) steps on by this row `in`; `out` gets the columns within reach.
PROJTRACK_VECTOR_CLONES void column_step(const std::uint8_t* __restrict__ in,
                                         std::uint8_t* __restrict__ d,
                                         std::uint8_t* __restrict__ out, int w, std::uint8_t cap) {
  for (int x = 0; x < w; ++x) {
    const std::uint8_t next = d[x] < cap ? static_cast<std::uint8_t>(d[x] + 1) : cap;
    const std::uint8_t v = in[x] ? 0 : next;
    d[x] = v;
    out[x] |= static_cast<std::uint8_t>(v < cap);
  }
}

}  // namespace

void MaskOps::spread(const Mask& src, int r, bool invert, Mask& dst) {
  const Rect& rect = src.rect();
  const int w = rect.width, h = rect.height;
  dst.reset(rect);
  if (w == 0 || h == 0) return;
  // Rows: each run of seed pixels (set ones; unset ones when inverting, outside the mask
  // included) marks itself and r pixels either side. dst was cleared by reset().
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* in = src.row(y);
    std::uint8_t* out = dst.row(y);
    const auto mark = [&](int a, int b) {  // the run [a, b], spread, clipped to the row
      const int x0 = std::max(0, a - r), x1 = std::min(w - 1, b + r);
      if (x0 <= x1) std::fill(out + x0, out + x1 + 1, 1);
    };
    if (invert) {
      mark(-1, -1);
      mark(w, w);
    }
    for (int x = next_run(in, 0, w, !invert); x < w;) {
      const int end = next_run(in, x, w, invert);
      mark(x, end - 1);
      x = next_run(in, end, w, !invert);
    }
  }
  // Columns, row by row: distance to the nearest reached row above, then below (saturated at
  // r + 1, in bytes, so that the loops vectorise).
  const int cap = std::min(r, 254) + 1;
  column_.assign(static_cast<std::size_t>(w), static_cast<std::uint8_t>(invert ? 0 : cap));
  tmp_.reset(rect);
  const auto pass = [&](int y) {
    column_step(dst.row(y), column_.data(), tmp_.row(y), w, static_cast<std::uint8_t>(cap));
  };
  for (int y = 0; y < h; ++y) pass(y);
  std::fill(column_.begin(), column_.end(), static_cast<std::uint8_t>(invert ? 0 : cap));
  for (int y = h - 1; y >= 0; --y) pass(y);
  dst.swap(tmp_);
  if (invert) {
    for (int y = 0; y < h; ++y) {
      std::uint8_t* out = dst.row(y);
      for (int x = 0; x < w; ++x) out[x] = !out[x];
    }
  }
}

void MaskOps::dilate(const Mask& src, int r, Mask& dst) { spread(src, std::max(0, r), false, dst); }

void MaskOps::erode(const Mask& src, int r, Mask& dst) { spread(src, std::max(0, r), true, dst); }

std::pair<Point2i, double> MaskOps::deepest(const Mask& m) {
  const int w = m.rect().width, h = m.rect().height;
  distance_.assign(static_cast<std::size_t>(w) * h, 0);
  const auto d = [&](int x, int y) -> int& {
    return distance_[static_cast<std::size_t>(y) * w + x];
  };
  // Two chamfer passes (3 along a row or column, 4 diagonally); outside the mask counts as unset.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!m.row(y)[x]) continue;
      int v = 3;  // next to the border
      if (x > 0 && y > 0) {
        v = std::min({d(x - 1, y) + 3, d(x, y - 1) + 3, d(x - 1, y - 1) + 4,
                      x + 1 < w ? d(x + 1, y - 1) + 4 : 3});
      }
      d(x, y) = v;
    }
  }
  std::pair<Point2i, double> best{{}, 0};
  int best_v = 0;
  for (int y = h - 1; y >= 0; --y) {
    for (int x = w - 1; x >= 0; --x) {
      if (!m.row(y)[x]) continue;
      int v = d(x, y);
      if (x + 1 < w && y + 1 < h) {
        v = std::min({v, d(x + 1, y) + 3, d(x, y + 1) + 3, d(x + 1, y + 1) + 4,
                      x > 0 ? d(x - 1, y + 1) + 4 : 3});
      } else {
        v = 3;
      }
      d(x, y) = v;
    }
  }
  for (int y = 0; y < h; ++y) {  // raster order for the ties
    for (int x = 0; x < w; ++x) {
      if (d(x, y) > best_v) {
        best_v = d(x, y);
        best.first = {x + m.rect().x, y + m.rect().y};
      }
    }
  }
  best.second = best_v / 3.0;
  return best;
}

void MaskOps::convex_hull(const Mask& src, Mask& dst) {
  const Rect& r = src.rect();
  dst.reset(r);
  // The first and last set pixel of each row hold every hull vertex.
  points_.clear();
  for (int y = 0; y < r.height; ++y) {
    const std::uint8_t* row = src.row(y);
    int first = -1, last = -1;
    for (int x = 0; x < r.width; ++x) {
      if (!row[x]) continue;
      if (first < 0) first = x;
      last = x;
    }
    if (first < 0) continue;
    points_.push_back({first, y});
    if (last != first) points_.push_back({last, y});
  }
  if (points_.empty()) return;
  // Andrew's monotone chain over points sorted by (x, y).
  std::sort(points_.begin(), points_.end(),
            [](Point2i a, Point2i b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto cross = [](Point2i o, Point2i a, Point2i b) {
    return static_cast<long long>(a.x - o.x) * (b.y - o.y) -
           static_cast<long long>(a.y - o.y) * (b.x - o.x);
  };
  hull_.assign(2 * points_.size(), {});
  std::size_t k = 0;
  for (const Point2i& p : points_) {
    while (k >= 2 && cross(hull_[k - 2], hull_[k - 1], p) <= 0) --k;
    hull_[k++] = p;
  }
  for (std::size_t i = points_.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull_[k - 2], hull_[k - 1], points_[i]) <= 0) --k;
    hull_[k++] = points_[i];
  }
  hull_.resize(k > 1 ? k - 1 : k);
  // Each row: the span between the hull's edges that cross it (pixel centres inside or on).
  for (int y = 0; y < r.height; ++y) {
    double lo = 1e18, hi = -1e18;
    for (std::size_t i = 0; i < hull_.size(); ++i) {
      const Point2i a = hull_[i], b = hull_[(i + 1) % hull_.size()];
      if ((a.y - y) * static_cast<long long>(b.y - y) > 0) continue;  // the edge misses the row
      if (a.y == b.y) {
        lo = std::min({lo, static_cast<double>(a.x), static_cast<double>(b.x)});
        hi = std::max({hi, static_cast<double>(a.x), static_cast<double>(b.x)});
        continue;
      }
      const double x = a.x + static_cast<double>(y - a.y) * (b.x - a.x) / (b.y - a.y);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    if (lo > hi) continue;
    std::uint8_t* d = dst.row(y);
    const int x0 = std::max(0, static_cast<int>(std::ceil(lo - 1e-9)));
    const int x1 = std::min(r.width - 1, static_cast<int>(std::floor(hi + 1e-9)));
    for (int x = x0; x <= x1; ++x) d[x] = 1;
  }
}

void MaskOps::outline(const Mask& m, std::vector<Point2i>& out) const {
  out.clear();
  const Rect& r = m.rect();
  for (int y = 0; y < r.height; ++y) {
    const std::uint8_t* row = m.row(y);
    const std::uint8_t* up = y > 0 ? m.row(y - 1) : nullptr;
    const std::uint8_t* down = y + 1 < r.height ? m.row(y + 1) : nullptr;
    for (int x = 0; x < r.width; ++x) {
      if (!row[x]) continue;
      const bool edge = x == 0 || x + 1 == r.width || !up || !down || !row[x - 1] || !row[x + 1] ||
                        !up[x] || !down[x];
      if (edge) out.push_back({x + r.x, y + r.y});
    }
  }
}

}  // namespace projtrack
