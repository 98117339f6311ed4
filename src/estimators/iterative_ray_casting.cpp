#include "estimators/iterative_ray_casting.hpp"

#include "estimators/ray_casting.hpp"

namespace projtrack {

// Centroid and area come from the last iteration's fan; the inner point walks toward each
// centroid in turn (the paper recentres it only once, after the loop: the common update).
void IterativeRayCasting::run(const Context& ctx, Features& out, Work& work) {
  iterate(ctx, out, work, false, [&](Point2i p, int iteration) {
    hits_.clear();
    const Point2d c = cast_fan(ctx.edges, p, ctx.fan, hits_, work);
    if (work.stopped) return c;  // fewer hits than rays: void
    out.area = fan_area(hits_.data(), ctx.fan.count(), p);
    out.bbox = fan_bounds(p, hits_);
    trace_fan(ctx.trace, p, hits_.data(), ctx.fan.count(), iteration, 1);
    return c;
  });
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::IterativeRayCasting>() {
  return std::make_unique<IterativeRayCasting>();
}

}  // namespace projtrack
