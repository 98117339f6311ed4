#include "acquisition/motion_acquisition.hpp"

#include <algorithm>

#include "acquisition/motion_gate.hpp"
#include "core/plausibility.hpp"
#include "projtrack/inner_point.hpp"

namespace projtrack {

namespace {

double share_inside(const std::vector<Point2i>& points, const Rect& r) {
  if (points.empty()) return 0;
  std::size_t n = 0;
  for (const Point2i& p : points) n += r.contains(p);
  return static_cast<double>(n) / points.size();
}

}  // namespace

std::optional<Features> MotionAcquisition::acquire(const ImageView& gray, const ImageView& edges,
                                                   Estimator& est, const Params& params,
                                                   double limit, const TrackerParams& tp,
                                                   WorkBudget& budget, std::string& why) {
  EstimateOptions options;
  options.budget = &budget;
  why = wait_for_motion(motion_, gray, tp.motion, tp.min_motion, moved_);
  if (!why.empty()) return std::nullopt;
  std::vector<Point2i> candidates{round_to_pixel(moved_.centroid)};
  if (tp.strategy == AutoAcquisition::CompactMovingRegion) {
    const std::size_t n = moved_.points.size(), k = std::max(1, tp.candidates);
    for (std::size_t i = 0; i < k && i < n; ++i) candidates.push_back(moved_.points[i * n / k]);
  }
  std::optional<Features> best;
  double best_score = -1;
  options.area_limit = limit;
  std::size_t tried = 0;
  too_large_.ensure(edges.width, edges.height);
  const Rect last = too_large_box_ & Rect{0, 0, edges.width, edges.height};
  too_large_.clear(last);
  budget.spend(clearing_cost(last.width, last.height));
  too_large_box_ = {};
  bool estimated = false;  // on this frame's edges
  for (const Point2i& c : candidates) {
    if (budget.exhausted()) break;  // one budget for every seed: what is left is not tried
    if (best && best->bbox.contains(c)) continue;  // already inside the best region found
    // Started (at the free pixel the estimate would start from) in the region the last fill
    // took in, or in one too large to be the object (the background the seeds before leaked
    // into, as a rule): the same verdict again.
    const std::optional<Point2i> start = nearest_free_pixel(edges, c, params.seed_radius);
    if (start && ((estimated && est.took_in(*start)) || too_large_.at(*start))) {
      if (*start != c) {  // the square searched for it, as an estimate counts it
        const std::uint64_t side = 2 * static_cast<std::uint64_t>(params.seed_radius) + 1;
        budget.spend(side * side);
      }
      continue;
    }
    estimated = true;
    Features f = est.estimate(edges, c, params, options);
    tried += f.status != EstimateStatus::OverBudget && f.status != EstimateStatus::Interrupted;
    if (limit > 0 && f.area > limit)  // cut short by the limit: a region too large
      budget.spend(est.add_fill_to(too_large_, too_large_box_));
    if (!why_implausible(f, edges.width, edges.height, tp).empty()) continue;
    // A sliver between two edges (seen on real footage: a 2×23 px strip) is not an object.
    if (std::min(f.bbox.width, f.bbox.height) < tp.min_acquired_side) continue;
    if (tp.strategy == AutoAcquisition::MotionCentroid) return f;
    // Moving (holds changed pixels) and compact (fills its box), unlike a background region.
    const double box = static_cast<double>(f.bbox.width) * f.bbox.height;
    const double score = share_inside(moved_.points, f.bbox) * f.area / box;
    if (score > best_score) {
      best_score = score;
      best = std::move(f);
    }
  }
  if (!best && (budget.ran_out() || budget.interrupted()))
    why = "the frame's work budget ran out (" + std::to_string(budget.spent()) + " of " +
          std::to_string(budget.limit()) + " units) after " + std::to_string(tried) + " of " +
          std::to_string(candidates.size()) + " seeds";
  else if (!best)
    why = "no closed region where the frame moved (" + std::to_string(candidates.size()) +
          " seeds tried)";
  return best;
}

}  // namespace projtrack
