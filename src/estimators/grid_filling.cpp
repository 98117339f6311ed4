#include "estimators/grid_filling.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {
// The first coordinate >= from on the grid of period m through `anchor`.
int first_on_grid(int from, int anchor, int m) {
  const int phase = ((anchor - from) % m + m) % m;
  return from + phase;
}
}  // namespace

GridFilling::Span GridFilling::extend(const Context& ctx, bool vertical, int at, int start,
                                      Work& work) {
  const ImageView& edges = ctx.edges;
  int a = start, b = start;
  if (!vertical) {
    const std::uint8_t* e = edges.row(at);
    const std::uint8_t* r = reached_.row(at);
    while (a > 0 && !e[a - 1] && !(r[a - 1] & kAlongRow)) --a;
    while (b < edges.width - 1 && !e[b + 1] && !(r[b + 1] & kAlongRow)) ++b;
  } else {
    const std::uint8_t* e = edges.data + at;
    const std::uint8_t* r = reached_.row(0) + at;
    const std::ptrdiff_t es = edges.stride, rs = reached_.stride();
    while (a > 0 && !e[(a - 1) * es] && !(r[(a - 1) * rs] & kAlongColumn)) --a;
    while (b < edges.height - 1 && !e[(b + 1) * es] && !(r[(b + 1) * rs] & kAlongColumn)) ++b;
  }
  work.fill(b - a + 2);
  if (vertical) work.cost += (kCostPerColumnPixel - 1) * (b - a + 2);
  return {a, b};
}

void GridFilling::run(const Context& ctx, Features& out, Work& work) {
  const ImageView& edges = ctx.edges;
  const int width = edges.width, height = edges.height, m = ctx.params.grid_size;
  const Point2i seed = out.seed;
  reached_.ensure(width, height);
  pending_.clear();
  pending_.push_back({seed, false});
  pending_.push_back({seed, true});
  std::uint64_t count = 0, sum_x = 0, sum_y = 0;
  BoundsAccumulator bounds;
  // Grid cells larger than the object make the scaling meaningless; the frame bounds it.
  const double cell = static_cast<double>(m) * m / (2.0 * m - 1.0);
  const double limit = ctx.options.area_limit > 0 ? ctx.options.area_limit : HUGE_VAL;

  while (!pending_.empty() && static_cast<double>(count) * cell <= limit && !work.must_stop()) {
    const Pending item = pending_.back();
    pending_.pop_back();
    const int x = item.p.x, y = item.p.y;
    work.fill(1);
    work.cost += kCostPerRun;
    const std::uint8_t bit = item.vertical ? kAlongColumn : kAlongRow;
    if (edges.row(y)[x] || (reached_.row(y)[x] & bit)) continue;
    const int at = item.vertical ? x : y;
    const Span s = extend(ctx, item.vertical, at, item.vertical ? y : x, work);
    for (int i = s.first; i <= s.last; ++i) {
      const int px = item.vertical ? x : i, py = item.vertical ? i : y;
      std::uint8_t& cell_bits = reached_.row(py)[px];
      if (!cell_bits) {
        ++count;
        sum_x += px;
        sum_y += py;
      }
      cell_bits |= bit;
    }
    const Point2i first = item.vertical ? Point2i{x, s.first} : Point2i{s.first, y};
    const Point2i last = item.vertical ? Point2i{x, s.last} : Point2i{s.last, y};
    bounds.add(first.x, first.y);
    bounds.add(last.x, last.y);
    if (ctx.trace) ctx.trace->runs.push_back({first, last});
    // The crossing grid lines of the other direction, where this run meets them.
    const int anchor = item.vertical ? seed.y : seed.x;
    for (int g = first_on_grid(s.first, anchor, m); g <= s.last; g += m) {
      const int px = item.vertical ? x : g, py = item.vertical ? g : y;
      const std::uint8_t other = item.vertical ? kAlongRow : kAlongColumn;
      if (!(reached_.row(py)[px] & other)) {
        pending_.push_back({{px, py}, !item.vertical});
        work.cost += kCostPerCrossing;
      }
    }
  }

  out.area = std::min(static_cast<double>(count) * cell, static_cast<double>(width) * height);
  out.centroid = {static_cast<double>(sum_x) / count, static_cast<double>(sum_y) / count};
  out.bbox = bounds.rect();
  out.iterations = 1;
  if (ctx.trace) ctx.trace->iterations.push_back({seed, out.centroid, out.area});
  reached_.clear(out.bbox);
  work.cost += clearing_cost(out.bbox.width, out.bbox.height);
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::GridFilling>() {
  return std::make_unique<GridFilling>();
}

}  // namespace projtrack
