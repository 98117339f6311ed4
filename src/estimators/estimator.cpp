#include "projtrack/estimator.hpp"

#include <algorithm>

#include "projtrack/inner_point.hpp"

namespace projtrack {

EstimateStatus border_status(const Rect& bbox, int width, int height) {
  const bool left = bbox.x <= 0, top = bbox.y <= 0;
  const bool right = bbox.right() >= width, bottom = bbox.bottom() >= height;
  if (left && top && right && bottom) return EstimateStatus::CoversFrame;
  if (left || top || right || bottom) return EstimateStatus::ReachedBorder;
  return EstimateStatus::Ok;
}

void translate(Features& f, int dx, int dy) {
  f.reach.x += dx;
  f.reach.y += dy;
  f.centroid.x += dx;
  f.centroid.y += dy;
  f.bbox.x += dx;
  f.bbox.y += dy;
  f.seed.x += dx;
  f.seed.y += dy;
  f.inner_point.x += dx;
  f.inner_point.y += dy;
}

Features Estimator::estimate(const ImageView& edges, Point2i inner_point, const Params& params,
                             const EstimateOptions& options, Trace* trace) {
  Features f;
  f.seed = f.inner_point = inner_point;
  if (trace) trace->clear();
  if (edges.empty()) {
    f.status = EstimateStatus::EmptyImage;
    f.detail = "the edge map has no pixels";
    return f;
  }
  if (!edges.valid()) {
    f.status = EstimateStatus::InvalidImage;
    f.detail = "stride " + std::to_string(edges.stride) + " is smaller than width " +
               std::to_string(edges.width);
    return f;
  }
  std::string why = validate(params);
  if (why.empty()) why = validate(options);
  if (!why.empty()) {
    f.status = EstimateStatus::InvalidParameters;
    f.detail = std::move(why);
    return f;
  }
  const std::optional<Point2i> seed = nearest_free_pixel(edges, inner_point, params.seed_radius);
  if (!seed) {
    const bool outside = !edges.contains(inner_point.x, inner_point.y);
    f.status = outside ? EstimateStatus::InnerPointOutside : EstimateStatus::InnerPointOnEdge;
    f.detail = outside ? "the inner point lies outside the frame, beyond the seed radius"
                       : "the inner point and every pixel within the seed radius are edges";
    return f;
  }
  f.seed = f.inner_point = *seed;
  fan_.set_count(params.rays);
  Work work;
  work.budget = options.budget;
  if (f.seed != inner_point) {  // the square searched for a free pixel
    const std::uint64_t side = 2 * static_cast<std::uint64_t>(params.seed_radius) + 1;
    work.cost += side * side;
  }
  if (!work.must_stop()) run(Context{edges, params, options, fan_, trace}, f, work);
  if (!work.stopped)
    f.inner_point =
        update_inner_point(edges, f.inner_point, f.centroid, fan_, update_hits_, work, trace, 0);
  if (options.budget) options.budget->spend(work.cost);
  f.rays_cast = work.rays;
  f.pixels_visited = work.pixels;
  if (work.stopped) return stopped(f, *options.budget, work);
  f.status = border_status(f.bbox, edges.width, edges.height);
  work.reach.add(f.bbox);
  f.reach = work.reach.rect();
  return f;
}

Features Estimator::stopped(Features& f, const WorkBudget& budget, const Work& work) {
  f.centroid = {};
  f.area = 0;
  f.bbox = {};
  f.reach = work.reach.rect();
  f.inner_point = f.seed;
  f.iterations = 0;
  if (budget.interrupted()) {
    f.status = EstimateStatus::Interrupted;
    f.detail = "stopped before the end: the caller's stop flag was set";
  } else {
    f.status = EstimateStatus::OverBudget;
    f.detail = "the work budget ran out: " + std::to_string(budget.spent()) + " of " +
               std::to_string(budget.limit()) + " units spent, " + std::to_string(work.cost) +
               " by this estimate";
  }
  return f;
}

std::unique_ptr<Estimator> make_estimator(Method m) {
  return is_method(m) ? method_info(m).make() : nullptr;
}

std::uint64_t least_estimate_cost(Method m, const Params& params) {
  const std::uint64_t n = std::clamp(params.rays, kMinRays, kMaxRays);
  const bool casts = is_method(m) && method_info(m).family == Family::Rays;
  const int levels = !casts ? 0
                     : method_info(m).reads & kReadsRecursion
                         ? std::clamp(params.recursion, kMinRecursion, kMaxRecursion)
                         : 1;
  std::uint64_t rays = n;  // the inner-point update's fan
  for (std::uint64_t level = 1, fans = 1; level <= static_cast<std::uint64_t>(levels); ++level) {
    rays += fans * n;  // one cast: n rays from every hit of the level before
    fans *= n;
  }
  return rays * (kCostPerRay + kCostPerRayStep);
}

}  // namespace projtrack
