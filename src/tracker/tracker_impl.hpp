// Tracker's hidden part, shared by the files of src/tracker/: the state between frames
// (tracker_state.hpp), the object model (src/models/, made from the table), the buffers of one
// frame's work, and the steps of one frame. One frame flows one way: the frame's evidence (its
// edges, its work images: models/frame_evidence.hpp) → the object model's observation (a
// silhouette, or an estimate on the edges) → the estimator on a silhouette (silhouette_estimate)
// → the verdict every model shares (core/plausibility, and the model's veto; verdict.cpp) → the
// pointer (pointer/) → TrackResult.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <string>

#include "core/mask.hpp"
#include "edges/edge_source.hpp"
#include "models/object_model.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "segmentation/work_images.hpp"
#include "tracker/silhouette_estimate.hpp"
#include "tracker/tracker_state.hpp"

namespace projtrack {

// The buffers of one frame's work: nothing in them means anything once the frame is done.
struct FrameWork {
  EdgeMap edge_map;
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators;  // made on first use
  WorkBudget budget;  // this frame's: every stage spends from it
  SilhouetteEstimateBuffers on_silhouette;
  FrameEvidence::ImageSlots images;  // the frame at working scales (FrameEvidence::images)

  Estimator& estimator(Method m);
};

// What one frame is given besides its pixels.
struct FrameInput {
  double t = 0;  // seconds
  Method method;
  const Params& params;
  const TrackerParams& tp;
  Trace* trace = nullptr;
};

struct Tracker::Impl {
  TrackerState state;
  ObjectModelKind kind = TrackerParams{}.model;
  std::unique_ptr<ObjectModel> model = make_object_model(kind);
  FrameWork work;
  const std::atomic<bool>* stop = nullptr;
  int width = 0, height = 0;  // the last frame's size (Tracker::silhouette())

  // One frame (tracker.cpp): its budget, its checks, then step().
  TrackResult track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult check_and_track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  // The model of `k`, with the track's user start kept when it is another than the last frame's.
  void use_model(ObjectModelKind k);
  // A new object (the user's start), or none: the model forgets its own, the track is reset.
  void forget_object();

  // The step every model shares (step.cpp): a start or the followed object, the estimate on its
  // silhouette, the verdict, and the model told of it.
  TrackResult step(FrameEvidence& ev, const FrameInput& in);
  // The start request the track holds: the user's mask, box or point, or nothing.
  StartRequest start_request() const;
  // The estimate of `o` (a silhouette, or the model's own estimate).
  Features estimate(FrameEvidence& ev, const Observation& o);
  // Why `f` is not this track's estimate (empty: it is): the rule every model shares, for a
  // start (`starting`) or a followed object, then the model's veto.
  Veto judge(FrameEvidence& ev, const Features& f, const Observation& o, bool starting);

  // The tracker's verdicts on a frame's estimate, as its result (verdict.cpp). accept: `f` is
  // this frame's (`resumed`: the object found again by its model). refuse: the last accepted
  // estimate is reported with `status` and why; the policy may drop the track (`drop_now`: drop
  // it whatever the count). stopped: the frame's work ran out or was interrupted before an
  // estimate.
  void accept(const Features& f, int width, int height, const FrameInput& in, bool resumed,
              TrackResult& r);
  void refuse(std::string why, const TrackerParams& tp, TrackResult& r,
              TrackStatus status = TrackStatus::Lost, bool drop_now = false);
  void stopped(const Features& f, const TrackerParams& tp, TrackResult& r);
  // A start that found nothing acceptable (`why`): the user's start is refused (tried again for
  // a while), a search goes on with `status` (Searching; NoInnerPoint while waiting for one).
  TrackResult not_started(std::string why, bool seeded, const TrackerParams& tp,
                          TrackStatus status = TrackStatus::Searching);
  bool work_stopped() const { return work.budget.ran_out() || work.budget.interrupted(); }
};

}  // namespace projtrack
