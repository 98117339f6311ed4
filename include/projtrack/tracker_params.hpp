// Everything that tunes the tracker, stage by stage.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "flow_model_params.hpp"
#include "gesture.hpp"
#include "motion_params.hpp"
#include "smoothing_params.hpp"

namespace projtrack {

// How tracking starts when there is no object.
enum class Acquisition {
  Manual,  // wait for an inner point (a property or a click)
  Center,  // try the frame centre
  Auto,    // the most relevant object: see AutoAcquisition (edges); the flow model takes a lost
           // object found again by its colours, else the object that moves apart from the
           // picture's own motion (src/models/flow/flow_search.cpp)
};

// How Acquisition::Auto picks the object with the edges model (compared in docs/benchmarks.md).
enum class AutoAcquisition {
  MotionCentroid,       // the original system's: the centroid of the changed pixels
  CompactMovingRegion,  // the changed pixels as candidate seeds; the most compact moving fill
};

// What the tracker knows of the object between frames: one value per row of
// object_model_table.def (flow: the whole object carried along the picture's motion and cut from
// its surroundings, the default; edges: the paper's tracker on the edge image alone).
// docs/tracker.md says what each does.
enum class ObjectModelKind {
#define PROJTRACK_OBJECT_MODEL(id, value, nick, description) id = value,
#include "object_model_table.def"
#undef PROJTRACK_OBJECT_MODEL
};

struct TrackerParams {
  ObjectModelKind model = ObjectModelKind::Flow;
  Acquisition acquisition = Acquisition::Auto;
  AutoAcquisition strategy = AutoAcquisition::CompactMovingRegion;
  MotionParams motion{25, 4};
  double min_motion = 0.0005;  // share of the frame that must change before Auto looks
  int candidates = 12;         // seeds CompactMovingRegion tries per frame
  int min_acquired_side = 8;   // px: a region thinner than this is not acquired

  // An estimate is refused (status Lost) when its area leaves [1/leak_factor, leak_factor] × the
  // last accepted one (a leak, or the inner point fell into a small region), exceeds
  // max_area × the frame, falls under min_area × the frame, or has no features at all.
  double leak_factor = 2.0;
  double max_area = 0.5;
  double min_area = 0.0005;
  int patience = 5;  // refused frames in a row tolerated; the next one drops the track

  // Edges model: while tracking, edges are needed only around the object: the last box, and that
  // box moved by the object's last motion, grown by this share of its larger side (at least
  // 16 px). An estimate that reaches the region's edge is redone on a region grown by four times
  // the margin, then on the whole frame. Negative: always the whole frame.
  double edge_margin = 0.1;

  // Flow model: how it carries and cuts the object.
  FlowModelParams flow;
  // After a loss the object is searched by its colours; after this many frames without finding
  // it, its colours are forgotten and Auto acquisition looks for any moving object.
  int forget_after = 150;

  // The work one frame may do, as a multiple of the frame's pixels (at least kLeastBudgetPixels),
  // in work units (about what one pixel of a fill costs, a nanosecond or so; work_budget.hpp):
  // every stage of the frame spends from it (the work images, the motion, the object model's
  // cut, acquisition's seeds, every estimate). A frame that runs out ends with
  // TrackStatus::OverBudget. 0: unlimited. See frame_work_limit().
  double max_work = 8;

  bool smoothing = true;  // One Euro filter on x, y and depth
  SmoothingParams filter;
  GestureParams push;  // push, press and release from depth (the element's push-threshold)
};

// The ranges of the settings whose limits are no other constant's: the element's property specs
// and validate(Settings) (Python's keywords) both read them, so both refuse the same values.
struct SettingRange {
  double low, high;
  bool contains(double v) const { return v >= low && v <= high; }  // false for NaN
};
inline constexpr SettingRange kLeakFactorRange{1.05, 1000.0};
inline constexpr SettingRange kSmoothingMinCutoffRange{0.01, 100.0};  // Hz
inline constexpr SettingRange kSmoothingBetaRange{0.0, 1000.0};
inline constexpr SettingRange kPushThresholdRange{0.01, 10.0};
inline constexpr SettingRange kEdgeThresholdRange{0.0, 10000.0};  // gradient magnitude

// The least budget a frame gets, work units: a tiny frame can still afford the default rays.
inline constexpr std::uint64_t kLeastFrameWork = 1 << 18;
// A frame's budget counts at least this many pixels (1.5 megapixels: 1080p's budget is its own,
// a smaller frame's that of a 1.5 MP one): the flow model's work is the object's (its silhouette
// and surroundings at the object's own scale, its motion), not the frame's, and a small frame
// holds an object as costly to follow as a large one does. At the default max_work that is
// about three times what a frame of the flow model costs on davis-dev (bench/davis, 2026-11-29).
inline constexpr double kLeastBudgetPixels = 1.5 * (1 << 20);
inline constexpr double kMaxMaxWork = 1e6;

// The work budget of one width × height frame: TrackerParams::max_work × its pixels (at least
// kLeastBudgetPixels), at least kLeastFrameWork; WorkBudget::kUnlimited (all bits set) when
// max_work is 0 (or not a number).
inline std::uint64_t frame_work_limit(int width, int height, const TrackerParams& tp) {
  if (!(tp.max_work > 0)) return ~std::uint64_t{0};
  const double pixels = static_cast<double>(std::max(width, 0)) * std::max(height, 0);
  const double limit = std::min(tp.max_work, kMaxMaxWork) * std::max(pixels, kLeastBudgetPixels);
  return std::max(kLeastFrameWork, static_cast<std::uint64_t>(std::min(limit, 1e18)));
}

}  // namespace projtrack
