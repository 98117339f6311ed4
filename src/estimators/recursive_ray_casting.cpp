#include "estimators/recursive_ray_casting.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

// Marks the pixels whose centres lie in triangle (a, b, c), counting the newly marked ones.
std::uint64_t mark_triangle(Point2d a, Point2d b, Point2d c, ScratchMask& mask, int width,
                            int height, BoundsAccumulator& bounds, Work& work) {
  const double y_min = std::min({a.y, b.y, c.y}), y_max = std::max({a.y, b.y, c.y});
  const int y0 = std::max(0, static_cast<int>(std::ceil(y_min)));
  const int y1 = std::min(height - 1, static_cast<int>(std::floor(y_max)));
  const Point2d edges[3][2] = {{a, b}, {b, c}, {c, a}};
  std::uint64_t added = 0, marked = 0;
  for (int y = y0; y <= y1; ++y) {
    double x_lo = HUGE_VAL, x_hi = -HUGE_VAL;
    for (const auto& e : edges) {
      const Point2d p = e[0], q = e[1];
      if ((y < p.y && y < q.y) || (y > p.y && y > q.y)) continue;
      if (p.y == q.y) {
        x_lo = std::min({x_lo, p.x, q.x});
        x_hi = std::max({x_hi, p.x, q.x});
      } else {
        const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
        x_lo = std::min(x_lo, x);
        x_hi = std::max(x_hi, x);
      }
    }
    const int x0 = std::max(0, static_cast<int>(std::ceil(x_lo)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(x_hi)));
    if (x0 > x1) continue;
    std::uint8_t* row = mask.row(y);
    for (int x = x0; x <= x1; ++x) {
      added += row[x] == 0;
      row[x] = 1;
    }
    marked += x1 - x0 + 1;
    bounds.add_run(x0, x1, y);
  }
  // A row's ends cost about two units (three edges intersected); its pixels are marked by a loop
  // the compiler vectorises.
  work.pixels += marked;
  work.cost +=
      2 * static_cast<std::uint64_t>(std::max(0, y1 - y0 + 1)) + marked / kScannedPixelsPerCost;
  return added;
}

}  // namespace

void RecursiveRayCasting::run(const Context& ctx, Features& out, Work& work) {
  iterate(ctx, out, work, true, [&](Point2i p, int iteration) {
    return cast_.cast(ctx.edges, p, ctx.fan, ctx.params.recursion, work, ctx.trace, iteration,
                      [](int, int) {});
  });
  if (work.stopped) return;  // the last fans are incomplete

  // The area swept by the last iteration's last level of rays.
  const int n = ctx.fan.count();
  covered_.ensure(ctx.edges.width, ctx.edges.height);
  BoundsAccumulator covered_bounds, bounds;
  std::uint64_t count = 0;
  const auto& origins = cast_.origins();
  const auto& hits = cast_.hits();
  for (std::size_t f = 0; f < origins.size() && !work.stopped; ++f) {
    const Point2d o = to_double(origins[f]);
    bounds.add(origins[f].x, origins[f].y);
    for (int k = 0; k < n && !work.must_stop(); ++k) {
      const RayHit& a = hits[f * n + k];
      const RayHit& b = hits[f * n + (k + 1) % n];
      bounds.add(a.last_free.x, a.last_free.y);
      count += mark_triangle(o, a.hit, b.hit, covered_, ctx.edges.width, ctx.edges.height,
                             covered_bounds, work);
    }
  }
  const Rect covered = covered_bounds.rect();
  covered_.clear(covered);
  work.cost += clearing_cost(covered.width, covered.height);
  out.area = static_cast<double>(count);
  out.bbox = bounds.rect();
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::RecursiveRayCasting>() {
  return std::make_unique<RecursiveRayCasting>();
}

}  // namespace projtrack
