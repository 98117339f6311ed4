#include "estimators/rasterized_ray_casting.hpp"

namespace projtrack {

void RasterizedRayCasting::run(const Context& ctx, Features& out, Work& work) {
  const int m = ctx.params.block_size;
  const int width = ctx.edges.width, height = ctx.edges.height;
  const int blocks_x = (width + m - 1) / m;
  const int blocks_y = (height + m - 1) / m;
  selected_.assign(static_cast<std::size_t>(blocks_x) * blocks_y, 0);
  work.cost += clearing_cost(selected_.size());

  double area = 0, sum_x = 0, sum_y = 0;
  BoundsAccumulator bounds;
  int iteration = 0;
  const auto select = [&](int x, int y) {
    const int bx = x / m, by = y / m;
    const std::size_t index = static_cast<std::size_t>(by) * blocks_x + bx;
    if (selected_[index]) return;
    selected_[index] = 1;
    const Rect r = clip_to_frame({bx * m, by * m, m, m}, width, height);
    const double a = static_cast<double>(r.width) * r.height;
    area += a;
    sum_x += a * (r.x + 0.5 * (r.width - 1));
    sum_y += a * (r.y + 0.5 * (r.height - 1));
    bounds.add(r);
    if (ctx.trace) ctx.trace->blocks.push_back({r, iteration});
  };

  iterate(ctx, out, work, true, [&](Point2i p, int it) {
    iteration = it;
    cast_.cast(ctx.edges, p, ctx.fan, ctx.params.recursion, work, ctx.trace, it, select);
    out.area = area;
    return Point2d{sum_x / area, sum_y / area};
  });
  out.bbox = bounds.rect();
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::RasterizedRayCasting>() {
  return std::make_unique<RasterizedRayCasting>();
}

}  // namespace projtrack
