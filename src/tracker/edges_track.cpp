// The edges model's step: the paper's tracker, the estimator on the frame's edges from the inner
// point, with the original system's motion acquisition.
#include "core/plausibility.hpp"
#include "tracker/acquisition_policy.hpp"
#include "tracker/edge_region.hpp"
#include "tracker/tracker_impl.hpp"

namespace projtrack {

TrackResult Tracker::Impl::track_edges(const ColorView& frame, EdgeSource& edges,
                                       const FrameInput& in) {
  TrackResult r;
  const int w = frame.luma.width, h = frame.luma.height;
  const TrackerState::Track& track = state.track();
  const Features* last = track.last ? &*track.last : nullptr;
  // The user's object from the point they gave until the track is dropped.
  const Origin origin = track.inner && (!last || track.seeded) ? Origin::User : Origin::Found;
  const double limit = area_limit(w, h, in.tp, last, origin);
  Estimator& est = work.estimator(in.method);
  if (!track.inner) {
    const std::optional<Features> f =
        start_edges_track(state, frame.luma, edges.region({0, 0, w, h}), est, in.params, limit,
                          in.tp, work.budget, r.detail);
    if (!f) {
      if (work_stopped()) {
        Features none;
        none.detail = std::move(r.detail);
        stopped(none, in.tp, r);
        return r;
      }
      r.status = in.tp.acquisition == Acquisition::Manual ? TrackStatus::NoInnerPoint
                                                          : TrackStatus::Searching;
      return r;
    }
    r.detail.clear();
    accept(*f, w, h, in, false, r);
    return r;
  }
  EstimateOptions limited;
  limited.area_limit = limit;
  limited.budget = &work.budget;
  const Features f =
      estimate_in_region(edges, est, in.method, *track.inner, last ? &last->bbox : nullptr,
                         track.velocity, in.params, limited, in.tp, in.trace);
  if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
    stopped(f, in.tp, r);
    return r;
  }
  // Not the object's doing: say what is wrong, keep the track.
  if (f.status == EstimateStatus::InvalidParameters || f.status == EstimateStatus::InvalidImage ||
      f.status == EstimateStatus::EmptyImage) {
    r.status = reported_status(f.status);
    r.features = f;
    return r;
  }
  if (std::string why = why_refused(f, w, h, in.tp, last, limit, origin); why.empty())
    accept(f, w, h, in, false, r);
  else
    refuse(std::move(why), in.tp, r);
  return r;
}

}  // namespace projtrack
