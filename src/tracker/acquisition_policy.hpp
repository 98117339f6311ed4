// The acquisition and re-acquisition policy, in one place: how a track starts (the user's point
// or box, the frame centre, the moving object, an object lost before found by its colours), when
// a lost object's colours are forgotten, which starts and tracks are vetoed (an arm running into
// the frame's border, the scene's background, a still object), and when refusals end a track.
// Functions over the tracker's state (tracker_state.hpp).
#pragma once

#include <optional>
#include <string>

#include "core/mask.hpp"
#include "edges/edge_source.hpp"
#include "projtrack/color_view.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/tracker_params.hpp"
#include "projtrack/work_budget.hpp"
#include "tracker/tracker_state.hpp"

namespace projtrack {

// The grey-level thresholds of motion and of the background scaled to a scene whose luma spans
// `spread` levels (TrackerParams::full_contrast; MotionDetector::spread()).
MotionDetector::Params motion_params(const TrackerParams& tp, int spread);
FinderParams finder_params(const TrackerParams& tp, int spread);

// What a track waits for when acquisition is manual and no point was given.
inline constexpr const char* kNoInnerPoint = "no inner point: set one, or click in the video";
inline bool waits_for_user(const TrackerState& s, const TrackerParams& tp) {
  return !s.track().inner && tp.acquisition == Acquisition::Manual;
}

// Edges model: the first estimate of a new track on `gray` and its `edges`, by
// TrackerParams::acquisition (the frame centre, or where the frame moves); none and `why` when
// there is nothing to take. The estimates spend from `budget` and fill up to `limit` px².
std::optional<Features> start_edges_track(TrackerState& s, const ImageView& gray,
                                          const ImageView& edges, Estimator& est,
                                          const Params& params, double limit,
                                          const TrackerParams& tp, WorkBudget& budget,
                                          std::string& why);

// Appearance model: the first silhouette of an object on `frame`, and the object model started
// (or resumed) on it: around the user's point or box, at the frame centre, where the colours of
// an object lost before are, or where the frame moves. A start without the user's point is
// vetoed when it runs into the frame's border or is the scene's background. `first` receives
// the finder's silhouette, `silhouette` the object model's.
struct AppearanceStart {
  bool found = false;
  bool resumed = false;  // the object lost before, found again by its colours
  std::string why;       // when not found
};
AppearanceStart start_appearance_track(TrackerState& s, const ColorView& frame, EdgeSource& edges,
                                       const TrackerParams& tp, Mask& first, Mask& silhouette);

// Appearance model, while tracking an object found without the user's point: whether it is a
// static region of the scene's background (its box hardly changes and its silhouette is what the
// background holds there) on this frame. Holds it (reported lost) for a few frames, then drops
// it. Updates the motion history with this frame.
enum class Stillness { Moves, Holds, Drop };
Stillness judge_stillness(TrackerState& s, const ColorView& frame, const Features& f,
                          const Mask& silhouette, const TrackerParams& tp);

// After a refused frame (TrackerState::refuse): whether the track ends, and why beyond the
// refusal. `forced`: the caller ends it whatever the count (a still object).
struct AfterRefusal {
  bool drop = false;
  std::string note;  // appended to the refusal's reason
};
AfterRefusal after_refusal(const TrackerState& s, const TrackerParams& tp, bool forced);
// Ends a track refused for good: the appearance model keeps the object's colours to find it
// again, unless the track held on one frame only; the edges model starts over.
void drop_refused_track(TrackerState& s);

}  // namespace projtrack
