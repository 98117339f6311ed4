#include "estimator.hpp"

#include "inner_point.hpp"

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
  run(Context{edges, params, options, fan_, trace}, f, work);
  f.inner_point =
      update_inner_point(edges, f.inner_point, f.centroid, fan_, update_hits_, work, trace, 0);
  f.status = border_status(f.bbox, edges.width, edges.height);
  work.reach.add(f.bbox);
  f.reach = work.reach.rect();
  f.rays_cast = work.rays;
  f.pixels_visited = work.pixels;
  return f;
}

std::unique_ptr<Estimator> make_estimator(Method m) {
  return is_method(m) ? method_info(m).make() : nullptr;
}

}  // namespace projtrack
