#include "estimators/ray_casting.hpp"

namespace projtrack {

Rect fan_bounds(Point2i origin, const std::vector<RayHit>& hits) {
  BoundsAccumulator b;
  b.add(origin.x, origin.y);
  for (const RayHit& h : hits) b.add(h.last_free.x, h.last_free.y);
  return b.rect();
}

void trace_fan(Trace* trace, Point2i origin, const RayHit* hits, int count, int iteration,
               int level) {
  if (!trace) return;
  for (int i = 0; i < count; ++i)
    trace->add_ray({to_double(origin), hits[i].hit, iteration, level});
}

void RayCasting::run(const Context& ctx, Features& out, Work& work) {
  hits_.clear();
  out.centroid = cast_fan(ctx.edges, out.seed, ctx.fan, hits_, work);
  if (work.stopped) return;  // fewer hits than rays: void
  out.area = fan_area(hits_.data(), ctx.fan.count(), out.seed);
  out.bbox = fan_bounds(out.seed, hits_);
  out.iterations = 1;
  trace_fan(ctx.trace, out.seed, hits_.data(), ctx.fan.count(), 1, 1);
  if (ctx.trace) ctx.trace->iterations.push_back({out.seed, out.centroid, out.area});
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::RayCasting>() {
  return std::make_unique<RayCasting>();
}

}  // namespace projtrack
