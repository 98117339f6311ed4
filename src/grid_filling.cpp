#include "grid_filling.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {
constexpr std::uint8_t kAlongRow = 1, kAlongColumn = 2;

// The first coordinate >= from on the grid of period m through `anchor`.
int first_on_grid(int from, int anchor, int m) {
  const int phase = ((anchor - from) % m + m) % m;
  return from + phase;
}
}  // namespace

void GridFilling::run(const Context& ctx, Features& out, Work& work) {
  const ImageView& edges = ctx.edges;
  const int width = edges.width, height = edges.height, m = ctx.params.grid_size;
  const Point2i seed = out.seed;
  reached_.ensure(width, height);
  const std::ptrdiff_t rstride = reached_.stride();
  pending_.clear();
  pending_.push_back({seed, false});
  pending_.push_back({seed, true});
  std::uint64_t count = 0, sum_x = 0, sum_y = 0;
  BoundsAccumulator bounds;
  // Grid cells larger than the object make the scaling meaningless; the frame bounds it.
  const double cell = static_cast<double>(m) * m / (2.0 * m - 1.0);
  const double limit = ctx.params.area_limit > 0 ? ctx.params.area_limit : HUGE_VAL;

  while (!pending_.empty() && static_cast<double>(count) * cell <= limit) {
    const Pending item = pending_.back();
    pending_.pop_back();
    const int x = item.p.x, y = item.p.y;
    ++work.pixels;
    if (!item.vertical) {
      const std::uint8_t* e = edges.row(y);
      std::uint8_t* r = reached_.row(y);
      if (e[x] || (r[x] & kAlongRow)) continue;
      int x0 = x, x1 = x;
      while (x0 > 0 && !e[x0 - 1] && !(r[x0 - 1] & kAlongRow)) --x0;
      while (x1 < width - 1 && !e[x1 + 1] && !(r[x1 + 1] & kAlongRow)) ++x1;
      work.pixels += x1 - x0 + 2;
      for (int i = x0; i <= x1; ++i) {
        if (!r[i]) {
          ++count;
          sum_x += i;
          sum_y += y;
        }
        r[i] |= kAlongRow;
      }
      bounds.add_run(x0, x1, y);
      if (ctx.trace) ctx.trace->runs.push_back({{x0, y}, {x1, y}});
      for (int gx = first_on_grid(x0, seed.x, m); gx <= x1; gx += m) {
        if (!(r[gx] & kAlongColumn)) pending_.push_back({{gx, y}, true});
      }
    } else {
      const std::uint8_t* e = edges.data + x;
      std::uint8_t* r = reached_.row(0) + x;
      const std::ptrdiff_t es = edges.stride;
      if (e[y * es] || (r[y * rstride] & kAlongColumn)) continue;
      int y0 = y, y1 = y;
      while (y0 > 0 && !e[(y0 - 1) * es] && !(r[(y0 - 1) * rstride] & kAlongColumn)) --y0;
      while (y1 < height - 1 && !e[(y1 + 1) * es] && !(r[(y1 + 1) * rstride] & kAlongColumn)) ++y1;
      work.pixels += y1 - y0 + 2;
      for (int i = y0; i <= y1; ++i) {
        std::uint8_t& cell = r[i * rstride];
        if (!cell) {
          ++count;
          sum_x += x;
          sum_y += i;
        }
        cell |= kAlongColumn;
      }
      bounds.add(x, y0);
      bounds.add(x, y1);
      if (ctx.trace) ctx.trace->runs.push_back({{x, y0}, {x, y1}});
      for (int gy = first_on_grid(y0, seed.y, m); gy <= y1; gy += m) {
        if (!(r[gy * rstride] & kAlongRow)) pending_.push_back({{x, gy}, false});
      }
    }
  }

  out.area = std::min(static_cast<double>(count) * cell, static_cast<double>(width) * height);
  out.centroid = {static_cast<double>(sum_x) / count, static_cast<double>(sum_y) / count};
  out.bbox = bounds.rect();
  out.iterations = 1;
  if (ctx.trace) ctx.trace->iterations.push_back({seed, out.centroid, out.area});
  reached_.clear(out.bbox);
}

}  // namespace projtrack
