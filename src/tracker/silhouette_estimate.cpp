#include "tracker/silhouette_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace projtrack {

namespace {

// The grid's and the blocks' cells are at most a kLeastCellsAcross-th of the object's √area: a
// small object is still measured by a few grid lines across, not by one or two (its outline is
// closed, so a finer grid costs work, never a leak).
constexpr double kLeastCellsAcross = 4;

int to_work(int v, int scale) { return v < 0 ? -1 : v / scale; }

// The frame rectangle the pieces are laid out in: the silhouette's, with one pixel of margin so
// that fills stop at it and rays end on it.
Rect layout_rect(const SilhouetteView& s) {
  const Rect f = to_frame(s.mask.rect(), s.scale, s.width, s.height);
  return clip_to_frame(Rect{f.x - 1, f.y - 1, f.width + 2, f.height + 2}, s.width, s.height);
}

// Piece `piece` (work coordinates) as an edge map over frame rectangle `r`: every pixel out of
// it is an edge; each work pixel of the piece clears its s×s block of frame pixels.
void lay_out(const Mask& piece, int scale, const Rect& r, std::vector<std::uint8_t>& barrier) {
  barrier.assign(static_cast<std::size_t>(r.width) * r.height, 255);
  const Rect& pr = piece.rect();
  for (int wy = 0; wy < pr.height; ++wy) {
    const std::uint8_t* in = piece.row(wy);
    const int y0 = std::max(r.y, (pr.y + wy) * scale);
    const int y1 = std::min(r.bottom(), (pr.y + wy + 1) * scale);
    for (int wx = 0; wx < pr.width; ++wx) {
      if (!in[wx]) continue;
      int run = wx;
      while (run + 1 < pr.width && in[run + 1]) ++run;
      const int x0 = std::max(r.x, (pr.x + wx) * scale);
      const int x1 = std::min(r.right(), (pr.x + run + 1) * scale);
      for (int y = y0; y < y1 && x0 < x1; ++y)
        std::fill_n(barrier.data() + static_cast<std::size_t>(y - r.y) * r.width + (x0 - r.x),
                    x1 - x0, 0);
      wx = run;
    }
  }
}

// The features of every piece, added up; `stopped` when an estimate ended the whole one (the
// budget, or the first piece's own failure): `total` is then that estimate.
struct PieceSum {
  Features total;
  double sx = 0, sy = 0;  // area-weighted centroid sums
  BoundsAccumulator box, reach;
  int pieces = 0;
  bool stopped = false;
};

PieceSum stopped_for_want_of_work(const WorkBudget& budget, int piece) {
  PieceSum out;
  out.stopped = true;
  out.total.status =
      budget.interrupted() ? EstimateStatus::Interrupted : EstimateStatus::OverBudget;
  out.total.detail =
      budget.interrupted()
          ? "stopped from outside before piece " + std::to_string(piece + 1) + " of the silhouette"
          : "the work budget ran out: " + std::to_string(budget.spent()) + " of " +
                std::to_string(budget.limit()) + " units spent, before piece " +
                std::to_string(piece + 1) + " of the silhouette";
  return out;
}

void add_piece(const Features& f, bool first, PieceSum& sum) {
  if (first) {
    sum.total = f;
  } else {
    sum.total.area += f.area;
    sum.total.iterations = std::max(sum.total.iterations, f.iterations);
    sum.total.rays_cast += f.rays_cast;
    sum.total.pixels_visited += f.pixels_visited;
  }
  sum.sx += f.area * f.centroid.x;
  sum.sy += f.area * f.centroid.y;
  sum.box.add(f.bbox);
  sum.reach.add(f.reach);
}

// One estimate per piece (the whole silhouette as one, unless `split`), each at full resolution
// on its piece alone; the largest piece first, from the inner point when it is in it.
PieceSum estimate_pieces(const SilhouetteView& s, const std::optional<Point2i>& inner,
                         Estimator& est, const Params& params, WorkBudget& budget,
                         SilhouetteEstimateBuffers& b, Trace* trace, bool split) {
  // The pieces are found at the object model's work scale; the grid's half-width is the neck.
  const int n = split ? b.pieces.split(s.mask, std::max(1, params.grid_size / (2 * s.scale)), 0.03)
                      : b.pieces.whole(s.mask);
  const Rect r = layout_rect(s);
  EstimateOptions closed;
  // The outline is closed: no leak to stop (no area limit) and no gap to tolerate (a narrow neck
  // of the object is not a break in its contour).
  closed.closed_outline = true;
  closed.budget = &budget;
  PieceSum sum;
  sum.pieces = n;
  for (int k = 0; k < n; ++k) {
    const std::uint64_t cost = clearing_cost(static_cast<std::size_t>(r.width) * r.height);
    if (budget.exhausted(cost)) return stopped_for_want_of_work(budget, k);
    budget.spend(cost);
    lay_out(b.pieces.piece(k), s.scale, r, b.barrier);
    // The inner point starts the first estimate; the split's, from each piece's deepest point (a
    // fill from the inner point that covered little of the silhouette was walled in there: a
    // pocket among specks of its outline).
    Point2i start;
    if (!split && k == 0 && inner &&
        b.pieces.piece_at({to_work(inner->x, s.scale), to_work(inner->y, s.scale)}) == 0) {
      start = *inner;
    } else {
      const Point2i deep = b.pieces.deepest(k);
      start = {deep.x * s.scale + s.scale / 2, deep.y * s.scale + s.scale / 2};
    }
    Trace* t = k == 0 ? trace : (trace ? &b.piece_trace : nullptr);
    Features f = est.estimate(ImageView(b.barrier.data(), r.width, r.height, r.width),
                              {start.x - r.x, start.y - r.y}, params, closed, t);
    translate(f, r.x, r.y);
    if (t) t->translate(r.x, r.y);
    if (t && t != trace) trace->append(*t);
    const bool work_stopped =
        f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted;
    if (work_stopped || (!f.valid() && k == 0)) {  // no estimate of the whole silhouette
      sum.total = f;
      sum.stopped = true;
      return sum;
    }
    if (f.valid()) add_piece(f, k == 0, sum);
  }
  return sum;
}

}  // namespace

namespace {

Params cells_for(const SilhouetteView& s, const Params& given) {
  Params p = given;
  const double area = moments(s.mask).area * s.scale * s.scale;
  const int most = std::max(1, static_cast<int>(std::sqrt(area) / kLeastCellsAcross));
  p.grid_size = std::min(p.grid_size, most);
  p.block_size = std::min(p.block_size, most);
  return p;
}

}  // namespace

Features estimate_on_silhouette(const SilhouetteView& s, const std::optional<Point2i>& inner,
                                Estimator& est, Method m, const Params& given, WorkBudget& budget,
                                SilhouetteEstimateBuffers& buffers, Trace* trace) {
  const Params params = cells_for(s, given);
  PieceSum sum = estimate_pieces(s, inner, est, params, budget, buffers, trace, false);
  if (sum.stopped) return sum.total;
  // A fill that covers much less than the silhouette was kept out of part of it: once more, in
  // pieces. (Rays always see less of a shape that is not star-shaped around the inner point, and
  // are left so.)
  if (sum.pieces == 1 && sum.total.valid() && method_info(m).family == Family::Fill &&
      sum.total.area < 0.8 * moments(s.mask).area * s.scale * s.scale) {
    sum = estimate_pieces(s, inner, est, params, budget, buffers, trace, true);
    if (sum.stopped) return sum.total;
  }
  Features total = sum.total;
  if (sum.pieces == 0) {
    total.status = EstimateStatus::EmptyImage;
    total.detail = "the silhouette is empty";
    return total;
  }
  if (total.area > 0) total.centroid = {sum.sx / total.area, sum.sy / total.area};
  // The object's box is its silhouette's (what the mask and the overlay show): a grid's fill
  // reaches the outline from lines a cell apart, and its own box may fall short by as much.
  total.bbox = to_frame(moments(s.mask).bbox, s.scale, s.width, s.height) | sum.box.rect();
  total.reach = sum.reach.rect();
  if (trace) trace_outline(s, layout_rect(s), *trace);
  if (total.valid()) total.status = border_status(total.bbox, s.width, s.height);
  return total;
}

void trace_outline(const SilhouetteView& s, const Rect& r, Trace& trace) {
  trace.outline.clear();
  const auto in = [&](int x, int y) {
    return s.mask.at({to_work(x, s.scale), to_work(y, s.scale)});
  };
  for (int y = r.y; y < r.bottom(); ++y)
    for (int x = r.x; x < r.right(); ++x)
      if (in(x, y) && (!in(x - 1, y) || !in(x + 1, y) || !in(x, y - 1) || !in(x, y + 1)))
        trace.outline.push_back({x, y});
}

}  // namespace projtrack
