#include "projtrack/inner_point.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace projtrack {

std::optional<Point2i> nearest_free_pixel(const ImageView& edges, Point2i p, int radius) {
  if (edges.contains(p.x, p.y) && edges.at(p.x, p.y) == 0) return p;
  // Far outside (or at coordinates where p ± radius would overflow): nothing to search.
  const long long px = p.x, py = p.y;
  if (px < -radius || py < -radius || px >= 1LL * edges.width + radius ||
      py >= 1LL * edges.height + radius)
    return std::nullopt;
  std::optional<Point2i> best;
  long long best_d2 = static_cast<long long>(radius) * radius + 1;
  const Rect square = clip_to_frame({p.x - radius, p.y - radius, 2 * radius + 1, 2 * radius + 1},
                                    edges.width, edges.height);
  for (int y = square.y; y < square.bottom(); ++y) {
    for (int x = square.x; x < square.right(); ++x) {
      const long long dx = x - p.x, dy = y - p.y, d2 = dx * dx + dy * dy;
      if (d2 < best_d2 && edges.at(x, y) == 0) {
        best_d2 = d2;
        best = Point2i{x, y};
      }
    }
  }
  return best;
}

Point2i move_toward(const ImageView& edges, Point2i from, Point2i to, Work& work) {
  const int dx = to.x - from.x, dy = to.y - from.y;
  const int steps = std::max(std::abs(dx), std::abs(dy));
  if (steps == 0) return from;
  // 16.16 fixed point; multiplications, since shifting a negative value left is undefined.
  const std::int64_t sx = static_cast<std::int64_t>(dx) * 65536 / steps;
  const std::int64_t sy = static_cast<std::int64_t>(dy) * 65536 / steps;
  std::int64_t fx = static_cast<std::int64_t>(from.x) * 65536;
  std::int64_t fy = static_cast<std::int64_t>(from.y) * 65536;
  int x = from.x, y = from.y;
  for (int i = 1; i <= steps; ++i) {
    fx += sx;
    fy += sy;
    // The last step lands exactly on `to`, whatever the rounding of the fixed-point slope.
    const int nx = i == steps ? to.x : static_cast<int>((fx + 0x8000) >> 16);
    const int ny = i == steps ? to.y : static_cast<int>((fy + 0x8000) >> 16);
    work.steps(1);
    if (!edges.contains(nx, ny) || edges.at(nx, ny) != 0) break;
    if (nx != x && ny != y && edges.at(nx, y) != 0 && edges.at(x, ny) != 0) break;
    x = nx;
    y = ny;
  }
  return {x, y};
}

Point2i recentre(const ImageView& edges, Point2i p, const RayFan& fan, std::vector<RayHit>& scratch,
                 Work& work, Trace* trace, int iteration) {
  scratch.clear();
  const Point2d mean = cast_fan(edges, p, fan, scratch, work);
  if (work.stopped) return p;
  if (trace) {
    for (const RayHit& h : scratch) trace->add_ray({to_double(p), h.hit, iteration, 1});
  }
  return move_toward(edges, p, round_to_pixel(mean), work);
}

Point2i update_inner_point(const ImageView& edges, Point2i p, Point2d centroid, const RayFan& fan,
                           std::vector<RayHit>& scratch, Work& work, Trace* trace, int iteration) {
  const Point2i moved = move_toward(edges, p, round_to_pixel(centroid), work);
  return recentre(edges, moved, fan, scratch, work, trace, iteration);
}

}  // namespace projtrack
