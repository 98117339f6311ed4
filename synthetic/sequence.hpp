// Tracking sequences: a scene spec per frame, the tracker run over them, each frame judged
// against the truth.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "projtrack/tracker.hpp"
#include "scene.hpp"

namespace projtrack::synthetic {

struct SequenceStep {
  double true_area = 0;  // 0 when the object is out of the frame
  Point2d true_centroid;
  TrackResult result;
  bool visible = false;  // at least half of the object (as on the first frame) is in the frame
  bool sane = false;     // tracking, centroid and area within kSane* of the truth
};

// A frame is tracked sanely when the centroid is within this share of √(true area) of the truth
// and the area within this share of the true area (bench/paper/main.cpp records them in meta.json).
inline constexpr double kSaneCentroid = 0.1;
inline constexpr double kSaneArea = 0.35;

// Renders frames spec(0..n-1) at 30 fps and tracks them; `seed` is given before the first frame.
std::vector<SequenceStep> run_sequence(int n, const std::function<SceneSpec(int)>& spec,
                                       const TrackerParams& tp,
                                       std::optional<Point2i> seed = std::nullopt,
                                       Method m = Method::GridFilling, const Params& p = {});

// A frame's spec with the object at (x, y), fresh sensor noise per frame.
SceneSpec frame_at(Object o, double x, double y, int frame, double scale = 1.0);

}  // namespace projtrack::synthetic
