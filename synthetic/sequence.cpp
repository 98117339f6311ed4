#include "sequence.hpp"

#include <cmath>

namespace projtrack::synthetic {

std::vector<SequenceStep> run_sequence(int n, const std::function<SceneSpec(int)>& spec,
                                       const TrackerParams& tp, std::optional<Point2i> seed,
                                       Method m, const Params& p) {
  Tracker tracker;
  if (seed) tracker.seed(*seed);
  std::vector<SequenceStep> steps;
  double first_area = -1;
  for (int i = 0; i < n; ++i) {
    const Scene s = make_scene(spec(i), EdgeParams{});
    if (first_area < 0) first_area = s.true_area;
    SequenceStep step;
    step.true_area = s.true_area;
    step.true_centroid = s.true_centroid;
    step.result = tracker.track(s.gray_view(), s.edge_view(), i / 30.0, m, p, tp);
    step.visible = s.true_area > 0.5 * first_area;
    const Features& f = step.result.features;
    step.sane = has_features(step.result.status) && s.true_area > 0 &&
                distance(f.centroid, s.true_centroid) < kSaneCentroid * std::sqrt(s.true_area) &&
                std::abs(f.area / s.true_area - 1) < kSaneArea;
    steps.push_back(step);
  }
  return steps;
}

SceneSpec frame_at(Object o, double x, double y, int frame, double scale) {
  SceneSpec s;
  s.object = o;
  s.centre = Point2d{x, y};
  s.instance = frame;
  s.scale = scale;
  return s;
}

}  // namespace projtrack::synthetic
