#include "estimators/gap_tolerant_filling.hpp"

#include <algorithm>

#include "core/byte_words.hpp"
#include "core/vector_clones.hpp"

namespace projtrack {

namespace {

// A run of a grid line and the band beside it: position i (0 <= i < n) of the run is pixel
// first + i along the row `at`, or along the column `at` when vertical.
struct RunBand {
  const ImageView& edges;
  bool vertical;
  int at, first, n;
  int reach;  // max_gap + 1: how far across the line an edge counts

  int none() const { return reach + 1; }  // no edge within reach

  // The pixel `offset` px across the line from position i (negative: above or left of it).
  Point2i pixel(int i, int offset) const {
    return vertical ? Point2i{at + offset, first + i} : Point2i{first + i, at + offset};
  }
};

// One side of the line, per position of the run: the offset of the nearest edge pixel within
// reach (or none), and of the nearest contour end, filled in lazily (0: not yet known).
struct Side {
  const std::uint8_t* near;
  std::uint8_t* ends;
  int sign;  // -1: above or left of the line, +1: below or right
};
constexpr std::uint8_t kUnknown = 0;

// What a run costs whatever its length, and its band's pixels; and what it reads: the run and the
// band, one pixel more for the contour-end test.
void charge_run(const RunBand& run, Work& work) {
  // The band's rows and the windows set up on both sides: measured, a run of a few pixels costs
  // as much as a few hundred pixels of a fill.
  work.fill(1);
  work.cost += 16 * static_cast<std::uint64_t>(run.reach);
  const int a = run.first, b = run.first + run.n - 1, at = run.at, reach = run.reach;
  if (run.vertical) {
    work.reach.add(at - reach - 1, a - 1);
    work.reach.add(at + reach + 1, b + 1);
  } else {
    work.reach.add(a - 1, at - reach - 1);
    work.reach.add(b + 1, at + reach + 1);
  }
  const std::uint64_t band = static_cast<std::uint64_t>(run.n) * 2 * reach;
  work.pixels += band;
  work.cost += band / kScannedPixelsPerCost;
}

// near[i] = off wherever the row has an edge: one pass of a row beside a horizontal line.
PROJTRACK_VECTOR_CLONES void mark_near(const std::uint8_t* __restrict__ row,
                                       std::uint8_t* __restrict__ near, int n, std::uint8_t off) {
  for (int i = 0; i < n; ++i) near[i] = row[i] ? off : near[i];
}

// The nearest edges above and below a run along a row (`above` and `below` hold none): whole rows
// beside it, long contiguous passes the compiler vectorises.
void find_edges_beside_row(const RunBand& run, std::uint8_t* above, std::uint8_t* below) {
  const ImageView& edges = run.edges;
  const int at = run.at;
  for (int t = run.reach; t >= 1; --t) {  // the nearest last, so it wins
    const auto off = static_cast<std::uint8_t>(t);
    if (at - t >= 0) mark_near(edges.row(at - t) + run.first, above, run.n, off);
    if (at + t < edges.height) mark_near(edges.row(at + t) + run.first, below, run.n, off);
  }
}

// The nearest edges left and right of a run along a column: 16 bytes a side of each row, two
// words at a time (byte by byte where the words would leave the frame).
void find_edges_beside_column(const RunBand& run, std::uint8_t* left, std::uint8_t* right) {
  const ImageView& edges = run.edges;
  const int at = run.at, across = edges.width, reach = run.reach, none = run.none();
  const bool words = at - 16 >= 0 && at + 17 <= across;
  for (int i = 0; i < run.n; ++i) {
    const std::uint8_t* e = edges.row(run.first + i);
    int d1 = none, d2 = none;
    if (words) {
      const std::uint64_t l0 = nonzero_bytes(load8(e + at - 8));
      const std::uint64_t l1 = nonzero_bytes(load8(e + at - 16));
      const std::uint64_t r0 = nonzero_bytes(load8(e + at + 1));
      const std::uint64_t r1 = nonzero_bytes(load8(e + at + 9));
      // Little-endian words: the byte nearest the line is the highest on the left, the lowest on
      // the right.
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
    left[i] = static_cast<std::uint8_t>(d1 <= reach ? d1 : none);
    right[i] = static_cast<std::uint8_t>(d2 <= reach ? d2 : none);
  }
}

// The kind of edge pixel at p: a contour's end (its edge neighbours, going round it, form one arc
// of at most three pixels, a quarter turn), a speck (no neighbours), or part of a contour
// (neighbours on two sides, or along half the ring: the side of a thick line).
enum class EdgeKind { End, Speck, Contour };
EdgeKind edge_kind(const ImageView& edges, Point2i p) {
  static constexpr int kRing[8][2] = {{0, -1}, {1, -1}, {1, 0},  {1, 1},
                                      {0, 1},  {-1, 1}, {-1, 0}, {-1, -1}};
  bool on[8];
  for (int k = 0; k < 8; ++k) {
    const int nx = p.x + kRing[k][0], ny = p.y + kRing[k][1];
    // Outside the frame counts as edge: a contour the border cuts does not end there.
    const bool outside = nx < 0 || ny < 0 || nx >= edges.width || ny >= edges.height;
    on[k] = outside || edges.row(ny)[nx];
  }
  int arcs = 0, count = 0;
  for (int k = 0; k < 8; ++k) {
    arcs += on[k] && !on[(k + 7) % 8];
    count += on[k];
  }
  if (count == 0) return EdgeKind::Speck;
  return arcs == 1 && count <= 3 ? EdgeKind::End : EdgeKind::Contour;
}

// The offset of the contour end nearest the line at position j on one side, or none: what a break
// leaves behind. Decided once per position, and only where edges lie on both sides of the line.
// Specks (sensor noise, one pixel) neither count nor hide what lies behind them; a contour does
// hide: the end of another contour beyond it is not this line's business.
int contour_end(const RunBand& run, Side& side, int j, Work& work) {
  if (side.near[j] == run.none()) return run.none();
  if (side.ends[j] == kUnknown) {
    int found = run.none();
    for (int t = side.near[j]; t <= run.reach; ++t) {
      const Point2i p = run.pixel(j, side.sign * t);
      const ImageView& edges = run.edges;
      if (p.x < 0 || p.y < 0 || p.x >= edges.width || p.y >= edges.height || !edges.row(p.y)[p.x])
        continue;
      const EdgeKind k = edge_kind(edges, p);
      work.fill(8);
      if (k == EdgeKind::Speck) continue;
      if (k == EdgeKind::End) found = t;
      break;
    }
    side.ends[j] = static_cast<std::uint8_t>(found);
  }
  return side.ends[j];
}

// Whether the line at position i passes between contour ends on its two sides, within reach along
// it (the run's own positions only), no farther apart across it than a break of max_gap px.
bool passes_gap(const RunBand& run, Side& s1, Side& s2, int i, Work& work) {
  const int j0 = std::max(0, i - run.reach), j1 = std::min(run.n - 1, i + run.reach);
  int m1 = run.none(), m2 = run.none();
  for (int j = j0; j <= j1; ++j) m1 = std::min(m1, contour_end(run, s1, j, work));
  if (m1 == run.none()) return false;
  for (int j = j0; j <= j1; ++j) m2 = std::min(m2, contour_end(run, s2, j, work));
  return m1 + m2 <= run.reach;
}

// The last position of the run walking from position s in direction d (-1 or +1), stopping
// before the first one where the line passes a gap. The sides of a narrow part are unbroken,
// and a corner's second side lies beyond the run's end, so neither stops a line. Counts of
// positions with an edge on each side within reach make the common case (edges on one side or
// none) one comparison.
int walk_to_gap(const RunBand& run, Side& s1, Side& s2, int s, int d, Work& work) {
  const int w = run.reach, last = d > 0 ? run.n - 1 : 0;
  int c1 = 0, c2 = 0;
  auto count = [&](int j, int sign) {
    if (j < 0 || j >= run.n) return;
    c1 += sign * (s1.near[j] != run.none());
    c2 += sign * (s2.near[j] != run.none());
  };
  for (int j = s - w; j <= s + w; ++j) count(j, +1);
  for (int i = s; i != last; i += d) {
    const int next = i + d;
    count(next + d * w, +1);
    count(next - d * (w + 1), -1);
    if (c1 > 0 && c2 > 0 && passes_gap(run, s1, s2, next, work)) return i;
  }
  return last;
}

}  // namespace

GridFilling::Span GapTolerantFilling::extend(const Context& ctx, bool vertical, int at, int start,
                                             Work& work) {
  // The plain grid run: up to an edge, the border or pixels this line already reached. On a
  // closed outline there is no gap to tolerate, and that is all (a narrow neck of the object is
  // no break in its contour).
  const Span plain = GridFilling::extend(ctx, vertical, at, start, work);
  if (ctx.options.closed_outline) return plain;
  const int n = plain.last - plain.first + 1;
  const RunBand run{ctx.edges, vertical, at, plain.first, n, ctx.params.max_gap + 1};
  charge_run(run, work);

  // The nearest edge within reach on each side of every position; then, from the start outwards,
  // the run up to where the line passes between contour ends: a gap.
  const auto none = static_cast<std::uint8_t>(run.none());
  near1_.assign(n, none);
  near2_.assign(n, none);
  if (vertical)
    find_edges_beside_column(run, near1_.data(), near2_.data());
  else
    find_edges_beside_row(run, near1_.data(), near2_.data());
  end1_.assign(n, kUnknown);
  end2_.assign(n, kUnknown);
  Side side1{near1_.data(), end1_.data(), -1}, side2{near2_.data(), end2_.data(), +1};
  const int s = start - run.first;
  return {run.first + walk_to_gap(run, side1, side2, s, -1, work),
          run.first + walk_to_gap(run, side1, side2, s, +1, work)};
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::GapTolerantFilling>() {
  return std::make_unique<GapTolerantFilling>();
}

}  // namespace projtrack
