#include "estimators/gap_tolerant_filling.hpp"

#include <algorithm>

#include "core/byte_words.hpp"
#include "core/vector_clones.hpp"

namespace projtrack {

namespace {

// near[i] = off wherever the row has an edge: one pass of a row beside a horizontal line.
PROJTRACK_VECTOR_CLONES void mark_near(const std::uint8_t* __restrict__ row,
                                       std::uint8_t* __restrict__ near, int n, std::uint8_t off) {
  for (int i = 0; i < n; ++i) near[i] = row[i] ? off : near[i];
}

}  // namespace

GridFilling::Span GapTolerantFilling::extend(const Context& ctx, bool vertical, int at, int start,
                                             Work& work) {
  // 1. The plain grid run: up to an edge, the border or pixels this line already reached. On a
  // closed outline there is no gap to tolerate, and that is all (a narrow neck of the object is
  // no break in its contour).
  const Span plain = GridFilling::extend(ctx, vertical, at, start, work);
  if (ctx.options.closed_outline) return plain;
  const ImageView& edges = ctx.edges;
  const int gap = ctx.params.max_gap;
  const int across = vertical ? edges.width : edges.height;
  const int a = plain.first, b = plain.last;
  work.fill(1);
  // What a run costs whatever its length: the band's rows and the windows set up on both sides
  // (measured: a run of a few pixels costs as much as a few hundred pixels of a fill).
  work.cost += 16 * static_cast<std::uint64_t>(gap + 1);

  // 2. For every position of the run, the offset across the line of the nearest edge pixel on
  // each side within reach = gap + 1 px, or none (gap + 2).
  const int reach = gap + 1, none = gap + 2;
  const int n = b - a + 1;
  // Everything read: the run and the band beside it, one pixel more for the contour-end test.
  if (vertical) {
    work.reach.add(at - reach - 1, a - 1);
    work.reach.add(at + reach + 1, b + 1);
  } else {
    work.reach.add(a - 1, at - reach - 1);
    work.reach.add(b + 1, at + reach + 1);
  }
  near1_.assign(n, static_cast<std::uint8_t>(none));
  near2_.assign(n, static_cast<std::uint8_t>(none));
  if (!vertical) {  // rows above and below: long contiguous passes the compiler vectorises
    for (int t = reach; t >= 1; --t) {  // the nearest last, so it wins
      const auto off = static_cast<std::uint8_t>(t);
      if (at - t >= 0) mark_near(edges.row(at - t) + a, near1_.data(), n, off);
      if (at + t < across) mark_near(edges.row(at + t) + a, near2_.data(), n, off);
    }
  } else {  // the pixels left and right in each row: 16 bytes a side, two words at a time
    const bool words = at - 16 >= 0 && at + 17 <= across;
    for (int i = 0; i < n; ++i) {
      const std::uint8_t* e = edges.row(a + i);
      int d1 = none, d2 = none;
      if (words) {
        const std::uint64_t l0 = nonzero_bytes(load8(e + at - 8));
        const std::uint64_t l1 = nonzero_bytes(load8(e + at - 16));
        const std::uint64_t r0 = nonzero_bytes(load8(e + at + 1));
        const std::uint64_t r1 = nonzero_bytes(load8(e + at + 9));
        // Little-endian words: the byte nearest the line is the highest on the left, the lowest
        // on the right.
        if (l0)
          d1 = __builtin_clzll(l0) / 8 + 1;
        else if (l1)
          d1 = __builtin_clzll(l1) / 8 + 9;
        if (r0)
          d2 = __builtin_ctzll(r0) / 8 + 1;
        else if (r1)
          d2 = __builtin_ctzll(r1) / 8 + 9;
      } else {
        for (int t = 1; t <= reach && d1 == none; ++t)
          if (at - t >= 0 && e[at - t]) d1 = t;
        for (int t = 1; t <= reach && d2 == none; ++t)
          if (at + t < across && e[at + t]) d2 = t;
      }
      near1_[i] = static_cast<std::uint8_t>(d1 <= reach ? d1 : none);
      near2_[i] = static_cast<std::uint8_t>(d2 <= reach ? d2 : none);
    }
  }
  const std::uint64_t band = static_cast<std::uint64_t>(n) * 2 * reach;
  work.pixels += band;
  work.cost += band / kScannedPixelsPerCost;

  // 3. Which of those nearest edges end a contour: what a break leaves behind. The sides of a
  // narrow part of the object are unbroken, so lines pass between them.
  // The kind of edge pixel at (x, y): a contour's end (its edge neighbours, going round it, form
  // one arc of at most three pixels, a quarter turn), a speck (no neighbours), or part of a
  // contour (neighbours on two sides, or along half the ring: the side of a thick line).
  enum class Kind { End, Speck, Contour };
  auto kind = [&](int x, int y) {
    static constexpr int kRing[8][2] = {{0, -1}, {1, -1}, {1, 0},  {1, 1},
                                        {0, 1},  {-1, 1}, {-1, 0}, {-1, -1}};
    bool on[8];
    for (int k = 0; k < 8; ++k) {
      const int nx = x + kRing[k][0], ny = y + kRing[k][1];
      // Outside the frame counts as edge: a contour the border cuts does not end there.
      const bool outside = nx < 0 || ny < 0 || nx >= edges.width || ny >= edges.height;
      on[k] = outside || edges.row(ny)[nx];
    }
    int arcs = 0, count = 0;
    for (int k = 0; k < 8; ++k) {
      arcs += on[k] && !on[(k + 7) % 8];
      count += on[k];
    }
    work.fill(8);
    if (count == 0) return Kind::Speck;
    return arcs == 1 && count <= 3 ? Kind::End : Kind::Contour;
  };
  constexpr std::uint8_t kUnknown = 0;
  end1_.assign(n, kUnknown);
  end2_.assign(n, kUnknown);
  // The offset of the contour end nearest the line at position j on one side (-1 or +1), or
  // none: decided lazily, once per position, only where edges lie on both sides of the line.
  // Specks (sensor noise, one pixel) neither count nor hide what lies behind them; a contour
  // does hide: the end of another contour beyond it is not this line's business.
  auto end_offset = [&](std::vector<std::uint8_t>& near, std::vector<std::uint8_t>& ends, int j,
                        int side) -> int {
    if (near[j] == none) return none;
    if (ends[j] == kUnknown) {
      int found = none;
      for (int t = near[j]; t <= reach; ++t) {
        const int o = side * t;
        const int x = vertical ? at + o : a + j, y = vertical ? a + j : at + o;
        if (x < 0 || y < 0 || x >= edges.width || y >= edges.height || !edges.row(y)[x]) continue;
        const Kind k = kind(x, y);
        if (k == Kind::Speck) continue;
        if (k == Kind::End) found = t;
        break;
      }
      ends[j] = static_cast<std::uint8_t>(found);
    }
    return ends[j];
  };

  // 4. From the start outwards, up to the first position where the line passes between contour
  // ends on its two sides (within w = reach px along it, the run's own positions only) no farther
  // apart across it than a break of `gap` px. The sides of a narrow part are unbroken, and a
  // corner's second side lies beyond the run's end, so neither stops a line.
  const int w = reach;
  auto crossing = [&](int i) {
    const int j0 = std::max(0, i - w), j1 = std::min(n - 1, i + w);
    int m1 = none, m2 = none;
    for (int j = j0; j <= j1; ++j) m1 = std::min(m1, end_offset(near1_, end1_, j, -1));
    if (m1 == none) return false;
    for (int j = j0; j <= j1; ++j) m2 = std::min(m2, end_offset(near2_, end2_, j, +1));
    return m1 + m2 <= reach;
  };
  // Walks from the start in direction d; counts of positions with an edge on each side in the
  // window make the common case (edges on one side or none) one comparison.
  auto extend = [&](int d) {
    const int s = start - a, last = d > 0 ? n - 1 : 0;
    int c1 = 0, c2 = 0;
    auto count = [&](int j, int sign) {
      if (j < 0 || j >= n) return;
      c1 += sign * (near1_[j] != none);
      c2 += sign * (near2_[j] != none);
    };
    for (int j = s - w; j <= s + w; ++j) count(j, +1);
    for (int i = s; i != last; i += d) {
      const int next = i + d;
      count(next + d * w, +1);
      count(next - d * (w + 1), -1);
      if (c1 > 0 && c2 > 0 && crossing(next)) return a + i;
    }
    return a + last;
  };
  return {extend(-1), extend(+1)};
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::GapTolerantFilling>() {
  return std::make_unique<GapTolerantFilling>();
}

}  // namespace projtrack
