#include "models/edges/edges_model.hpp"

#include "core/plausibility.hpp"
#include "models/edges/edge_region.hpp"

namespace projtrack {

template <>
std::unique_ptr<ObjectModel> make_object_model<ObjectModelKind::Edges>() {
  return std::make_unique<EdgesObjectModel>();
}

namespace {

// Whose object the track is: the user's from the point they gave until the track is dropped.
Origin origin_of(const Track& track) {
  return track.inner && (!track.last || track.seeded) ? Origin::User : Origin::Found;
}

}  // namespace

Observation EdgesObjectModel::start(FrameEvidence& ev, const StartRequest& request,
                                    const Track& track) {
  if (request.from != StartRequest::From::Nothing) return estimate_from(ev, request.point, track);
  const TrackerParams& tp = ev.tp;
  const int w = ev.width(), h = ev.height();
  const ImageView edges = ev.edges.region({0, 0, w, h});
  acquisition_.use_mode(tp.acquisition);
  Observation o;
  if (tp.acquisition == Acquisition::Center) {
    EstimateOptions options;
    options.budget = &ev.budget;
    o.kind = Observation::Kind::Estimate;
    o.estimate = ev.estimator.estimate(edges, {w / 2, h / 2}, ev.params, options);
    if (std::string why = why_implausible(o.estimate, w, h, tp); !why.empty())
      return Observation::missing("at the frame centre: " + why);
    return o;
  }
  const double limit = area_limit(w, h, tp, nullptr, Origin::Found);
  std::string why;
  const std::optional<Features> f = acquisition_.acquire(ev.frame.luma, edges, ev.estimator,
                                                         ev.params, limit, tp, ev.budget, why);
  if (!f) {
    if (ev.budget.ran_out() || ev.budget.interrupted()) {
      Features none;
      none.detail = std::move(why);
      return Observation::stopped(std::move(none));
    }
    return Observation::missing(std::move(why));
  }
  o.kind = Observation::Kind::Estimate;
  o.estimate = *f;
  o.area_limit = limit;
  return o;
}

Observation EdgesObjectModel::follow(FrameEvidence& ev, const Track& track) {
  return estimate_from(ev, track.inner ? *track.inner : Point2i{ev.width() / 2, ev.height() / 2},
                       track);
}

Observation EdgesObjectModel::estimate_from(FrameEvidence& ev, Point2i inner, const Track& track) {
  const Features* last = track.last ? &*track.last : nullptr;
  Observation o;
  o.kind = Observation::Kind::Estimate;
  o.area_limit = area_limit(ev.width(), ev.height(), ev.tp, last, origin_of(track));
  EstimateOptions limited;
  limited.area_limit = o.area_limit;
  limited.budget = &ev.budget;
  o.estimate =
      estimate_in_region(ev.edges, ev.estimator, ev.method, inner, last ? &last->bbox : nullptr,
                         track.velocity, ev.params, limited, ev.tp, ev.trace);
  return o;
}

void EdgesObjectModel::settle(Verdict verdict) {
  if (verdict == Verdict::Accepted) following_ = true;
}

bool EdgesObjectModel::rescale(double, double, int, int) {
  acquisition_.reset();  // its motion history is of frames of the old size
  return true;
}

void EdgesObjectModel::forget(Forget) {
  following_ = false;
  acquisition_.reset();
}

}  // namespace projtrack
