#include "models/appearance/appearance_object_model.hpp"

namespace projtrack {

template <>
std::unique_ptr<ObjectModel> make_object_model<ObjectModelKind::Appearance>() {
  return std::make_unique<AppearanceObjectModel>();
}

ColorView AppearanceObjectModel::as_read(const ColorView& raw, const TrackerParams& tp) {
  if (!m_.object.knows_colours())
    m_.exposure = exposure_for(luma_range(raw.luma), tp.dim_white, tp.full_contrast);
  ColorView frame = raw;
  frame.exposure = m_.exposure;
  return frame;
}

Observation AppearanceObjectModel::start(FrameEvidence& ev, const StartRequest& request,
                                         const Track& track) {
  step_ = track.last ? Step::Continuation : Step::Start;
  const ColorView frame = as_read(ev.frame, ev.tp);
  const AppearanceStart s =
      start_appearance_track(m_, frame, ev.edges, request, track, ev.tp, first_, silhouette_);
  if (!s.found) {
    step_ = Step::None;
    if (ev.budget.ran_out() || ev.budget.interrupted()) return Observation::stopped();
    return Observation::missing(s.why);
  }
  return Observation::of_silhouette(silhouette_, m_.object.scale(), s.resumed);
}

Observation AppearanceObjectModel::follow(FrameEvidence& ev, const Track& track) {
  step_ = Step::Follow;
  learning_ = ev.tp.object;
  const ColorView frame = as_read(ev.frame, ev.tp);
  const Point2i hint = track.inner ? *track.inner : Point2i{-1, -1};
  if (!m_.object.find(frame, ev.edges, track.velocity, hint, ev.tp.object, silhouette_)) {
    if (ev.budget.ran_out() || ev.budget.interrupted())  // its edges were cut short
      return Observation::stopped();
    return Observation::missing("nothing of the object's colours is left where it was");
  }
  return Observation::of_silhouette(silhouette_, m_.object.scale());
}

Veto AppearanceObjectModel::veto(FrameEvidence& ev, const Features& f, const Track& track) {
  // An object found without the user's point that the scene's background holds is not reported
  // as measured (held, as a refused estimate), and dropped after TrackerParams::still_frames
  // such frames in a row: a static region that motion around it picked (the original system
  // dropped an object that stopped moving). One the user pointed at is kept, whatever it is.
  if (step_ != Step::Follow || track.seeded || ev.tp.still_frames <= 0) return {};
  switch (judge_stillness(m_, as_read(ev.frame, ev.tp), f, silhouette_, ev.tp)) {
    case Stillness::Drop:
      return {"the object is part of the scene's background: a static region", true};
    case Stillness::Holds:
      return {"the object does not move and looks like the scene's background", false};
    case Stillness::Moves:
      break;
  }
  return {};
}

void AppearanceObjectModel::settle(Verdict verdict) {
  switch (step_) {
    case Step::Follow:
      if (verdict == Verdict::Accepted) m_.object.accept(silhouette_, learning_);
      break;
    case Step::Start:
      if (verdict != Verdict::Accepted) m_.object.forget_position();
      break;
    case Step::Continuation:
      // A continuation refused: its colours too, learned from what was no continuation of the
      // object, are not kept (a track dropped later would look for them).
      if (verdict == Verdict::Refused) m_.object.forget();
      if (verdict == Verdict::Stopped) m_.object.forget_position();
      break;
    case Step::None:
      break;
  }
  if (verdict == Verdict::Accepted) m_.searched = 0;
  step_ = Step::None;
}

bool AppearanceObjectModel::rescale(double sx, double sy, int, int) {
  // The silhouette follows and its colours stay: the next frame goes on as any other (a relearn
  // within the last box would learn the background there when the picture changed with the
  // size, as a clip joined to another). Without a silhouette to follow, the track relearns
  // within its box.
  if (!m_.object.tracking()) return relearn();
  m_.object.rescale(sx, sy);
  m_.forget_motion();
  return true;
}

bool AppearanceObjectModel::relearn() {
  // The start within the last box takes the object's first silhouette there and learns its
  // colours against the frame's border, as from a user's box.
  m_.object.forget();
  m_.forget_motion();
  return false;
}

void AppearanceObjectModel::forget(Forget what) {
  if (what == Forget::Position)
    m_.object.forget_position();
  else
    m_.object.forget();
  m_.forget_motion();
  m_.searched = 0;
  m_.still = 0;
  step_ = Step::None;
}

SilhouetteMask AppearanceObjectModel::silhouette(int frame_width, int frame_height) const {
  if (!m_.object.tracking()) return {};
  const Mask& s = m_.object.silhouette();
  return {s.view(), s.rect(), m_.object.scale(), frame_width, frame_height};
}

}  // namespace projtrack
