// One object's track: its model's lifetime and the tracker's verdicts on a frame's estimate.
#include "tracker/object_track.hpp"

#include <opencv2/imgproc.hpp>
#include <utility>

#include "tracker/refusal_policy.hpp"

namespace projtrack {

void ObjectTrack::use_model(ObjectModelKind k) {
  if (k == kind && model) return;
  state.switch_model();
  model = make_object_model(k);
  kind = k;
}

void ObjectTrack::forget_object() {
  model->forget(Forget::Everything);
  state.reset();
}

void ObjectTrack::seed(Point2i p) {
  forget_object();
  state.seed(p);
}

void ObjectTrack::seed_box(const Rect& box) {
  forget_object();
  state.seed_box(box);
}

bool ObjectTrack::seed_mask(const ImageView& mask) {
  if (mask.data == nullptr || mask.width <= 0 || mask.height <= 0 || mask.stride < mask.width)
    return false;
  cv::Mat inside;
  cv::compare(cv::Mat(mask.height, mask.width, CV_8U, const_cast<std::uint8_t*>(mask.data),
                      static_cast<std::size_t>(mask.stride)),
              0, inside, cv::CMP_GT);
  const cv::Rect b = cv::boundingRect(inside);
  if (b.empty()) return false;
  // The deepest point: the one farthest from the outline, well inside the object.
  cv::Mat distance;
  cv::distanceTransform(inside, distance, cv::DIST_L2, 3);
  cv::Point deepest;
  cv::minMaxLoc(distance, nullptr, nullptr, nullptr, &deepest);
  forget_object();
  state.seed_mask(inside, Rect{b.x, b.y, b.width, b.height}, {deepest.x, deepest.y});
  return true;
}

void ObjectTrack::rescale(double sx, double sy, int width, int height) {
  state.rescale(sx, sy, width, height);
  if (!model->rescale(sx, sy, width, height)) state.restart_within_last_box();
}

void ObjectTrack::relearn() {
  state.mark_across_change();
  if (!model->relearn()) state.restart_within_last_box();
}

void ObjectTrack::accept(const Features& f, int width, int height, const FrameInput& in,
                         bool resumed, TrackResult& r) {
  r.acquired = state.accept(f, resumed, in.t, width, height, in.tp);
  r.status = reported_status(f.status);
  r.features = f;
  r.has_pose = true;
  r.pose = state.pointer.pose();
  r.raw_pose = state.pointer.raw();
}

namespace {

// A result that reports the last accepted estimate (none yet: no features at all) and its pose.
void report_last(const TrackerState& s, TrackResult& r) {
  r.features = s.track().last ? *s.track().last : Features{};
  r.has_pose = s.track().last.has_value();
  r.pose = s.pointer.pose();
  r.raw_pose = s.pointer.raw();
}

}  // namespace

void ObjectTrack::refuse(std::string why, const TrackerParams& tp, TrackResult& r,
                         TrackStatus status, bool drop_now) {
  if (covered_by && status == TrackStatus::Lost && !drop_now && state.track().last) {
    r = occluded("object " + std::to_string(covered_by) + " is in front of it (" + why + ")");
    return;
  }
  r.status = status;
  r.detail = std::move(why);
  report_last(state, r);
  state.refuse();
  const AfterRefusal next = after_refusal(state.track(), tp, drop_now);
  if (next.drop && keeps_looking) {
    // Not dropped for another object: looked for again from where it was (or from the user's
    // start, never taken), its model keeping what it knows of it.
    r.detail += "; looked for again where it was last seen";
    model->forget(Forget::Position);
    state.lose();
    return;
  }
  r.detail += next.note;
  if (!next.drop) return;
  // A track accepted on one frame only was never an object: its model is not searched for.
  model->forget(state.track().accepted > 1 ? Forget::Position : Forget::Everything);
  state.drop();
}

TrackResult ObjectTrack::occluded(std::string why) {
  TrackResult r;
  r.status = TrackStatus::Occluded;
  r.detail = std::move(why);
  report_last(state, r);
  state.hide();
  return r;
}

TrackResult ObjectTrack::not_started(std::string why, bool seeded, const TrackerParams& tp,
                                     TrackStatus status) {
  TrackResult r;
  if (seeded) {  // the user's start: keep trying it for a while, as a refused estimate
    refuse(std::move(why), tp, r);
    return r;
  }
  r.status = status;
  r.detail = std::move(why);
  return r;
}

void ObjectTrack::stopped(const Features& f, const WorkBudget& budget, const TrackerParams& tp,
                          TrackResult& r) {
  std::string why = f.detail;
  if (f.status == EstimateStatus::Interrupted || budget.interrupted()) {
    // Said here whatever the stage that stopped said: a stop is no budget running out.
    r.status = TrackStatus::Interrupted;
    r.detail = "stopped from outside (the pipeline is stopping or flushing) after " +
               std::to_string(budget.spent()) + " work units: the track is kept as it was";
    report_last(state, r);
    return;
  }
  if (why.empty()) why = "the frame's work budget ran out";
  if (state.track().inner || state.track().last) {
    refuse(std::move(why), tp, r, TrackStatus::OverBudget);
    return;
  }
  r.status = TrackStatus::OverBudget;  // searching: the next frame searches again
  r.detail = std::move(why);
}

}  // namespace projtrack
