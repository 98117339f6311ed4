// The step every object model shares: a start or the followed object, the estimate on its
// silhouette, the verdict, and the model told of it. Written once: the model never sees the
// budget's outcome, the statuses or the pointer.
#include <cmath>

#include "core/plausibility.hpp"
#include "tracker/object_track.hpp"
#include "tracker/refusal_policy.hpp"

namespace projtrack {

namespace {

bool stops(const Features& f) {
  return f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted;
}

// Not the object's doing (the settings, the frame): said, and the track kept as it is.
bool unusable(const Features& f) {
  return f.status == EstimateStatus::InvalidParameters ||
         f.status == EstimateStatus::InvalidImage || f.status == EstimateStatus::EmptyImage;
}

// Whose object the track is, for the plausibility rules: the user's from the start they gave.
Origin origin_of(const Track& t) {
  const bool users = t.last ? t.seeded : t.inner.has_value();
  return users ? Origin::User : Origin::Found;
}

}  // namespace

StartRequest ObjectTrack::start_request() const {
  const Track& t = state.track();
  StartRequest r;
  if (!t.inner) return r;
  r.point = *t.inner;
  if (!t.seed_mask.empty()) {
    r.from = StartRequest::From::Mask;
    r.mask = &t.seed_mask;
    r.box = *t.seed_box;
  } else if (t.seed_box) {
    r.from = StartRequest::From::Box;
    r.box = *t.seed_box;
  } else {
    // A track with an accepted estimate whose model lost its object: found again, not a new one
    // started at the inner point (that point may now lie on the background).
    r.from = t.last ? StartRequest::From::Lost : StartRequest::From::Point;
  }
  return r;
}

Features ObjectTrack::estimate(FrameEvidence& ev, const Observation& o) {
  if (o.kind != Observation::Kind::Silhouette) return o.estimate;
  const SilhouetteView s{*o.silhouette, o.scale, ev.width(), ev.height()};
  return estimate_on_silhouette(s, state.track().inner, ev.estimator, ev.method, ev.params,
                                ev.budget, on_silhouette_, ev.trace);
}

Veto ObjectTrack::judge(FrameEvidence& ev, const Features& f, const Observation& o, bool starting) {
  const Track& t = state.track();
  const int w = ev.width(), h = ev.height();
  const Origin origin = origin_of(t);
  Veto v;
  if (!t.last) {
    v.why = why_implausible(f, w, h, ev.tp, origin);
  } else if (starting || t.across_change) {
    // A start that goes on a track whose last estimate was kept (a rescale or a relearn: the
    // model starts again within the last box) continues it: judged against the last estimate,
    // so a start that took a sliver of the object is no continuation that every next frame then
    // "jumps" from. Its colours learned anew, it may take another part of the object, and across
    // a new size or format the picture itself may have changed (a clip joined to another), so
    // its area may change by leak_factor² rather than leak_factor.
    TrackerParams restart = ev.tp;
    restart.leak_factor = ev.tp.leak_factor * ev.tp.leak_factor;
    v.why = why_refused(f, w, h, restart, &*t.last, HUGE_VAL, origin);
  } else {
    v.why = why_refused(f, w, h, ev.tp, &*t.last, o.area_limit, origin);
  }
  if (v.why.empty()) v = model->veto(ev, f, t);
  return v;
}

TrackResult ObjectTrack::step(FrameEvidence& ev, const FrameInput& in) {
  const Look l = look(ev, in);
  return l.done ? *l.done : conclude(ev, in, l);
}

Look ObjectTrack::look(FrameEvidence& ev, const FrameInput& in) {
  Look l;
  l.starting = !model->tracking();
  if (l.starting && waits_for_user(state.track(), in.tp)) {
    l.done = not_started(kNoInnerPoint, false, in.tp, TrackStatus::NoInnerPoint);
    return l;
  }
  l.seeded = state.track().inner.has_value();
  l.observation = l.starting ? model->start(ev, start_request(), state.track())
                             : model->follow(ev, state.track());
  return l;
}

TrackResult ObjectTrack::conclude(FrameEvidence& ev, const FrameInput& in, const Look& l) {
  const TrackerParams& tp = in.tp;
  const int w = ev.width(), h = ev.height();
  const Observation& o = l.observation;
  const bool work_stopped = ev.budget.ran_out() || ev.budget.interrupted();
  TrackResult r;
  if (o.kind == Observation::Kind::Stopped ||
      (o.kind == Observation::Kind::Missing && work_stopped)) {
    model->settle(Verdict::Stopped);
    stopped(o.estimate, ev.budget, tp, r);
    return r;
  }
  if (o.kind == Observation::Kind::Missing) {
    model->settle(Verdict::Refused);
    if (l.starting) return not_started(o.why, l.seeded, tp);
    refuse(o.why, tp, r);
    return r;
  }
  const Features f = estimate(ev, o);
  if (stops(f)) {
    model->settle(Verdict::Stopped);
    stopped(f, ev.budget, tp, r);
    return r;
  }
  if (unusable(f)) {  // the track is kept as it is
    model->settle(Verdict::Stopped);
    r.status = reported_status(f.status);
    r.features = f;
    return r;
  }
  const Veto v = judge(ev, f, o, l.starting);
  if (v.why.empty()) {
    model->settle(Verdict::Accepted);
    accept(f, w, h, in, o.resumed, r);
    return r;
  }
  model->settle(Verdict::Refused);
  if (l.starting && !v.drop) return not_started(v.why, l.seeded, tp);
  refuse(v.why, tp, r, TrackStatus::Lost, v.drop);
  return r;
}

}  // namespace projtrack
