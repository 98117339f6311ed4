#include "projtrack/tracker.hpp"

#include <utility>

#include "core/plausibility.hpp"
#include "tracker/refusal_policy.hpp"
#include "tracker/tracker_impl.hpp"

namespace projtrack {

Estimator& FrameWork::estimator(Method m) {
  auto& e = estimators[static_cast<int>(m)];
  if (!e) e = method_info(m).make();
  return *e;
}

Tracker::Tracker() : impl_(std::make_unique<Impl>()) {}
Tracker::~Tracker() = default;
Tracker::Tracker(Tracker&&) noexcept = default;
Tracker& Tracker::operator=(Tracker&&) noexcept = default;

void Tracker::seed(Point2i p) { impl_->object.seed(p); }
void Tracker::seed_box(const Rect& box) { impl_->object.seed_box(box); }
void Tracker::reset() { impl_->object.forget_object(); }
bool Tracker::seed_mask(const ImageView& mask) { return impl_->object.seed_mask(mask); }
const std::optional<Point2i>& Tracker::inner_point() const {
  return impl_->object.state.track().inner;
}
void Tracker::set_stop_flag(const std::atomic<bool>* stop) { impl_->stop = stop; }
void Tracker::relearn() { impl_->object.relearn(); }

void Tracker::rescale(int width, int height, int new_width, int new_height) {
  if (width <= 0 || height <= 0 || new_width <= 0 || new_height <= 0) return;
  impl_->object.rescale(static_cast<double>(new_width) / width,
                        static_cast<double>(new_height) / height, new_width, new_height);
}

SilhouetteMask Tracker::silhouette() const {
  if (!impl_->object.state.track().last) return {};
  return impl_->object.model->silhouette(impl_->width, impl_->height);
}

TrackResult Tracker::track(const ColorView& frame, const EdgeParams& edge_params, double t,
                           Method m, const Params& params, const TrackerParams& tp, Trace* trace) {
  EdgeSource edges(impl_->work.edge_map, frame.luma, edge_params);
  return impl_->track(frame, edges, FrameInput{t, m, params, tp, trace});
}
TrackResult Tracker::track(const ImageView& gray, const EdgeParams& edge_params, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  return track(ColorView{gray, {}, {}}, edge_params, t, m, params, tp, trace);
}
TrackResult Tracker::track(const ColorView& frame, const ImageView& edges, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  EdgeSource given(edges);
  return impl_->track(frame, given, FrameInput{t, m, params, tp, trace});
}
TrackResult Tracker::track(const ImageView& gray, const ImageView& edges, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  return track(ColorView{gray, {}, {}}, edges, t, m, params, tp, trace);
}

namespace {

// Why settings cannot work (empty when they can). Settings whose single estimate can never fit in
// the frame's `budget` (millions of rays per cast) would end every frame over budget.
std::string invalid_settings(const FrameInput& in, const EdgeParams& edge_params,
                             const WorkBudget& budget) {
  std::string bad = validate(in.params);
  if (bad.empty()) bad = validate(edge_params);
  if (bad.empty()) bad = validate(in.tp);
  if (const std::uint64_t least = least_estimate_cost(in.method, in.params);
      bad.empty() && least > budget.limit()) {
    bad = "one estimate with rays = " + std::to_string(in.params.rays) +
          (method_info(in.method).reads & kReadsRecursion
               ? " and recursion = " + std::to_string(in.params.recursion)
               : std::string()) +
          " costs at least " + std::to_string(least) +
          " work units, more than the frame's budget of " + std::to_string(budget.limit()) +
          " (max_work = " + std::to_string(in.tp.max_work) +
          " × its pixels): fewer rays or levels, or a larger max_work";
  }
  return bad;
}

TrackResult failed(TrackStatus status, std::string why) {
  TrackResult r;
  r.status = status;
  r.detail = std::move(why);
  return r;
}

}  // namespace

std::string frame_problem(const ColorView& frame, EdgeSource& edges, const FrameInput& in,
                          const WorkBudget& budget, TrackStatus& status) {
  const ImageView& luma = edges.frame();
  if (!luma.valid() || !frame.luma.valid() || frame.luma.width != luma.width ||
      frame.luma.height != luma.height) {
    status = luma.empty() ? TrackStatus::EmptyImage : TrackStatus::InvalidImage;
    return "no usable frame";
  }
  status = TrackStatus::InvalidParameters;
  return invalid_settings(in, edges.params(), budget);
}

ObjectModelKind model_for(const EdgeSource& edges, const TrackerParams& tp) {
  return edges.params().detector == EdgeDetector::Input ? ObjectModelKind::Edges : tp.model;
}

TrackResult Tracker::Impl::track(const ColorView& frame, EdgeSource& edges, const FrameInput& in) {
  work.budget = WorkBudget(frame_work_limit(frame.luma.width, frame.luma.height, in.tp), stop);
  width = frame.luma.width;
  height = frame.luma.height;
  edges.set_budget(&work.budget);
  TrackResult r = check_and_track(frame, edges, in);
  r.inner_point = object.state.track().inner;
  r.work = work.budget.spent();
  r.work_limit = work.budget.limit();
  r.gesture = object.state.pointer.take_gesture();  // whichever transition of the frame made it
  return r;
}

TrackResult Tracker::Impl::check_and_track(const ColorView& frame, EdgeSource& edges,
                                           const FrameInput& in) {
  if (in.trace) in.trace->clear();
  TrackStatus status;
  // The track waits for a usable frame and for settings that cannot work to be fixed.
  if (std::string bad = frame_problem(frame, edges, in, work.budget, status); !bad.empty())
    return failed(status, std::move(bad));
  if (work.budget.interrupted()) {  // nothing is started while the stop flag is set
    TrackResult r;
    object.stopped(Features{}, work.budget, in.tp, r);
    return r;
  }
  object.use_model(model_for(edges, in.tp));
  FrameEvidence ev(frame, edges, work.budget, work.estimator(in.method), in.method, in.params,
                   in.tp, in.trace, work.images);
  return object.step(ev, in);
}

}  // namespace projtrack
