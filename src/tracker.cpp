#include "tracker.hpp"

namespace projtrack {

Features Tracker::track(const ImageView& edges, Method m, const Params& params, Trace* trace) {
  if (trace) trace->clear();
  if (!inner_) {
    Features f;
    f.status = Status::NoInnerPoint;
    f.detail = "no inner point: set one, or click in the video";
    return f;
  }
  auto& estimator = estimators_[static_cast<int>(m)];
  if (!estimator) estimator = make_estimator(m);
  Features f = estimator->estimate(edges, *inner_, params, trace);
  if (f.valid()) inner_ = f.inner_point;
  return f;
}

}  // namespace projtrack
