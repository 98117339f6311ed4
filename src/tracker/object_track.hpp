// One object's track: the state kept between frames (tracker_state.hpp), its object model
// (src/models/, made from the table), and the step of one frame that every model shares. A
// Tracker holds one; a MultiTracker one per object, all served by one frame's evidence
// (models/frame_evidence.hpp). One frame flows one way: the object model's observation (a
// silhouette, or an estimate on the edges) → the estimator on a silhouette
// (silhouette_estimate) → the verdict every model shares (core/plausibility, and the model's
// veto) → the pointer (pointer/) → TrackResult.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "models/object_model.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "tracker/silhouette_estimate.hpp"
#include "tracker/tracker_state.hpp"

namespace projtrack {

// What one frame is given besides its pixels.
struct FrameInput {
  double t = 0;  // seconds
  Method method;
  const Params& params;
  const TrackerParams& tp;
  Trace* trace = nullptr;
};

// What the object model made of a frame, before the tracker's verdict on it: a MultiTracker
// settles where two objects' silhouettes meet between look() and conclude().
struct Look {
  std::optional<TrackResult> done;  // the frame needs no verdict (waiting for a start)
  Observation observation;
  bool starting = false;  // a start, not the followed object
  bool seeded = false;    // the user's start
};

class ObjectTrack {
 public:
  TrackerState state;
  ObjectModelKind kind = TrackerParams{}.model;
  std::unique_ptr<ObjectModel> model = make_object_model(kind);
  // Refusals never drop the track (a MultiTracker's object, which only the user ends): once the
  // policy would drop it, its model looks for it again where it was last seen.
  bool keeps_looking = false;
  // Another object (its id; 0: none) covers where this one was last seen on this frame: a refused
  // frame is then this object hidden by it, occluded (a MultiTracker sets it for conclude()).
  int covered_by = 0;

  // The model of `k`, with the track's user start kept when it is another than the last frame's.
  void use_model(ObjectModelKind k);
  // A new object (the user's start), or none: the model forgets its own, the track is reset.
  void forget_object();
  // The user's start, tracked from the next frame on (Tracker::seed, seed_box, seed_mask).
  void seed(Point2i p);
  void seed_box(const Rect& box);
  bool seed_mask(const ImageView& mask);
  // The frames change size (sx × sy, now width × height) or their colours are read another way
  // (Tracker::rescale, Tracker::relearn).
  void rescale(double sx, double sy, int width, int height);
  void relearn();

  // One frame's step (step.cpp): look() then conclude().
  TrackResult step(FrameEvidence& ev, const FrameInput& in);
  // A start or the followed object: the model's observation.
  Look look(FrameEvidence& ev, const FrameInput& in);
  // The estimate on the observation, the verdict, and the model told of it.
  TrackResult conclude(FrameEvidence& ev, const FrameInput& in, const Look& l);
  // The frame's work ran out or was interrupted (`budget`) before an estimate, or `f` stopped.
  void stopped(const Features& f, const WorkBudget& budget, const TrackerParams& tp,
               TrackResult& r);
  // The object is hidden by another on this frame: its last estimate is reported, Occluded, and
  // the track waits for it as for a refused frame, without counting towards dropping it.
  TrackResult occluded(std::string why);

 private:
  // The start request the track holds: the user's mask, box or point, or nothing.
  StartRequest start_request() const;
  // The estimate of `o` (a silhouette, or the model's own estimate).
  Features estimate(FrameEvidence& ev, const Observation& o);
  // Why `f` is not this track's estimate (empty: it is): the rule every model shares, for a
  // start (`starting`) or a followed object, then the model's veto.
  Veto judge(FrameEvidence& ev, const Features& f, const Observation& o, bool starting);
  // The verdicts on a frame's estimate, as its result (verdict.cpp). accept: `f` is this
  // frame's (`resumed`: the object found again by its model). refuse: the last accepted
  // estimate is reported with `status` and why; the policy may drop the track (`drop_now`: drop
  // it whatever the count).
  void accept(const Features& f, int width, int height, const FrameInput& in, bool resumed,
              TrackResult& r);
  void refuse(std::string why, const TrackerParams& tp, TrackResult& r,
              TrackStatus status = TrackStatus::Lost, bool drop_now = false);
  // A start that found nothing acceptable (`why`): the user's start is refused (tried again for
  // a while), a search goes on with `status` (Searching; NoInnerPoint while waiting for one).
  TrackResult not_started(std::string why, bool seeded, const TrackerParams& tp,
                          TrackStatus status = TrackStatus::Searching);

  SilhouetteEstimateBuffers on_silhouette_;
};

}  // namespace projtrack
