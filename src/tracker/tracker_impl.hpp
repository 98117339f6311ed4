// Tracker's hidden part, shared by the files of src/tracker/: the state between frames
// (tracker_state.hpp), the buffers of one frame's work, and the steps of one frame. One frame
// flows one way: the frame's edges (edges/) and appearance (appearance/) → the object's
// silhouette (the object model; acquisition/ when there is none) → the estimator on it
// (estimators/, silhouette_estimate.hpp) → the tracker's verdict (plausibility, the policy of
// acquisition_policy.hpp) → the pointer (pointer/) → TrackResult.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/mask.hpp"
#include "edges/edge_source.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "segmentation/work_images.hpp"
#include "tracker/acquisition_policy.hpp"
#include "tracker/silhouette_estimate.hpp"
#include "tracker/tracker_state.hpp"

namespace projtrack {

// The buffers of one frame's work: nothing in them means anything once the frame is done.
struct FrameWork {
  EdgeMap edge_map;
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators;  // made on first use
  WorkBudget budget;       // this frame's: every estimate spends from it
  Mask first, silhouette;  // the finder's first silhouette; the object model's on this frame
  SilhouetteEstimateBuffers on_silhouette;
  WorkImages images;  // the flow model's frame
  cv::Mat inside;     // the flow model's first silhouette

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
  FrameWork work;
  const std::atomic<bool>* stop = nullptr;
  int width = 0, height = 0;  // the last frame's size (Tracker::silhouette())

  // One frame (tracker.cpp): its budget, its checks, then the object model's step.
  TrackResult track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult check_and_track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  // The edges model's step (edges_track.cpp).
  TrackResult track_edges(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  // The appearance model's steps (appearance_track.cpp): a new object, or the tracked one.
  TrackResult track_appearance(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult start_appearance(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult follow_appearance(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  // The frame as the appearance model reads it (a dim one stretched: Exposure).
  ColorView as_appearance_reads(const ColorView& raw, const TrackerParams& tp);
  // The estimate on work.silhouette, a mask at `scale`.
  Features estimate_silhouette(const ColorView& frame, int scale, const FrameInput& in);
  // The flow model's steps (flow_track.cpp): a new object, or the tracked one.
  TrackResult track_flow(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult start_flow(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult follow_flow(const ColorView& frame, const FrameInput& in);
  // The flow model's first silhouette, into work.inside: the user's mask, GrabCut in the user's
  // box, or the appearance model's start (a point, or none).
  AppearanceStart first_flow_silhouette(const ColorView& frame, EdgeSource& edges,
                                        const FrameInput& in);
  // A point start of the flow model: GrabCut's candidates around the point against the
  // appearance model's first silhouette (work.inside, when `start` found it); the one the others
  // agree with most into work.inside.
  void choose_at_point(Point2i point, AppearanceStart& start);
  // The flow model's silhouette as the estimator reads it (work.silhouette), and its estimate.
  Features estimate_flow_silhouette(const ColorView& frame, const FrameInput& in);

  // The tracker's verdicts on a frame's estimate, as its result (tracker.cpp). accept: `f` is
  // this frame's (`resumed`: the object found again by its colours). refuse: the last accepted
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
