// The appearance model's step: the object's silhouette on every frame from its colours, its
// edges and its last silhouette, and the estimator on the silhouette's outline.
#include <cmath>

#include "core/plausibility.hpp"
#include "tracker/acquisition_policy.hpp"
#include "tracker/tracker_impl.hpp"

namespace projtrack {

namespace {

// Why `f`, the first estimate of the object model started within a box or from a point, is
// refused. A new track's needs only be plausible for its origin. One that goes on a track whose
// last estimate was kept (a rescale or a relearn: the model starts again within the last box)
// continues that track, as any frame of it: judged with the track's own origin against the last
// estimate (scaled), so a start that took a sliver of the object (25 px² of a 5 000 px² cup) is
// no continuation that every next frame's estimate then "jumps" from. Its colours learned anew,
// it may take another part of the object (on a gray frame the cup's body alone, 0.47× its colour
// silhouette), so its area may change by leak_factor² rather than leak_factor.
std::string why_not_first(const Features& f, int w, int h, const TrackerParams& tp,
                          const TrackerState::Track& track) {
  if (!track.last) return why_implausible(f, w, h, tp, track.inner ? Origin::User : Origin::Found);
  TrackerParams restart = tp;
  restart.leak_factor = tp.leak_factor * tp.leak_factor;
  return why_refused(f, w, h, restart, &*track.last, HUGE_VAL,
                     track.seeded ? Origin::User : Origin::Found);
}

}  // namespace

ColorView Tracker::Impl::as_appearance_reads(const ColorView& raw, const TrackerParams& tp) {
  if (!state.object.knows_colours())
    state.exposure = exposure_for(luma_range(raw.luma), tp.dim_white, tp.full_contrast);
  ColorView frame = raw;
  frame.exposure = state.exposure;
  return frame;
}

TrackResult Tracker::Impl::track_appearance(const ColorView& raw, EdgeSource& edges,
                                            const FrameInput& in) {
  // The frame as the appearance model reads it: a dim one stretched to a normal exposure. The
  // model's colours are learned under it, so it is measured only while no object is known and
  // held while one is: the frame's range changes with what moves through it (a bright object
  // that leaves a dim room), and the model follows slow changes of the light by itself.
  const ColorView frame = as_appearance_reads(raw, in.tp);
  return state.object.tracking() ? follow_appearance(frame, edges, in)
                                 : start_appearance(frame, edges, in);
}

Features Tracker::Impl::estimate_silhouette(const ColorView& frame, int scale,
                                            const FrameInput& in) {
  const SilhouetteView s{work.silhouette, scale, frame.luma.width, frame.luma.height};
  return estimate_on_silhouette(s, state.track().inner, work.estimator(in.method), in.method,
                                in.params, work.budget, work.on_silhouette, in.trace);
}

TrackResult Tracker::Impl::start_appearance(const ColorView& frame, EdgeSource& edges,
                                            const FrameInput& in) {
  if (waits_for_user(state, in.tp))
    return not_started(kNoInnerPoint, false, in.tp, TrackStatus::NoInnerPoint);
  TrackResult r;
  const int w = frame.luma.width, h = frame.luma.height;
  const bool seeded = state.track().inner.has_value();
  AppearanceStart start =
      start_appearance_track(state, frame, edges, in.tp, work.first, work.silhouette);
  if (start.found) {
    const Features f = estimate_silhouette(frame, state.object.scale(), in);
    if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
      state.object.forget_position();
      stopped(f, in.tp, r);
      return r;
    }
    start.why = why_not_first(f, w, h, in.tp, state.track());
    if (start.why.empty()) {
      accept(f, w, h, in, start.resumed, r);
      return r;
    }
    // A continuation refused: its colours too, learned from what was no continuation of the
    // object, are not kept (a track dropped later would look for them).
    if (state.track().last)
      state.object.forget();
    else
      state.object.forget_position();
  } else if (work_stopped()) {  // its edges were cut short
    stopped(Features{}, in.tp, r);
    return r;
  }
  return not_started(std::move(start.why), seeded, in.tp);
}

TrackResult Tracker::Impl::follow_appearance(const ColorView& frame, EdgeSource& edges,
                                             const FrameInput& in) {
  TrackResult r;
  const int w = frame.luma.width, h = frame.luma.height;
  const TrackerState::Track& track = state.track();
  const Point2i hint = track.inner ? *track.inner : Point2i{-1, -1};
  if (!state.object.find(frame, edges, track.velocity, hint, in.tp.object, work.silhouette)) {
    if (work_stopped())  // its edges were cut short
      stopped(Features{}, in.tp, r);
    else
      refuse("nothing of the object's colours is left where it was", in.tp, r);
    return r;
  }
  const Features f = estimate_silhouette(frame, state.object.scale(), in);
  if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
    stopped(f, in.tp, r);
    return r;
  }
  const Origin origin = track.seeded ? Origin::User : Origin::Found;
  if (std::string why =
          why_refused(f, w, h, in.tp, track.last ? &*track.last : nullptr, HUGE_VAL, origin);
      !why.empty()) {
    refuse(std::move(why), in.tp, r);
    return r;
  }
  // An object found without the user's point that the scene's background holds is not reported
  // as measured (held, as a refused estimate), and dropped after TrackerParams::still_frames
  // such frames in a row: a static region that motion around it picked (the original system
  // dropped an object that stopped moving). One the user pointed at is kept, whatever it is.
  if (!track.seeded && in.tp.still_frames > 0) {
    switch (judge_stillness(state, frame, f, work.silhouette, in.tp)) {
      case Stillness::Drop:
        refuse("the object is part of the scene's background: a static region", in.tp, r,
               TrackStatus::Lost, true);
        return r;
      case Stillness::Holds:
        refuse("the object does not move and looks like the scene's background", in.tp, r);
        return r;
      case Stillness::Moves:
        break;
    }
  }
  state.object.accept(work.silhouette, in.tp.object);
  accept(f, w, h, in, false, r);
  return r;
}

}  // namespace projtrack
