#include "projtrack/tracker.hpp"

#include <opencv2/imgproc.hpp>
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

void Tracker::seed(Point2i p) {
  impl_->forget_object();
  impl_->state.seed(p);
}
void Tracker::seed_box(const Rect& box) {
  impl_->forget_object();
  impl_->state.seed_box(box);
}
void Tracker::reset() { impl_->forget_object(); }

bool Tracker::seed_mask(const ImageView& mask) {
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
  impl_->forget_object();
  impl_->state.seed_mask(inside, Rect{b.x, b.y, b.width, b.height}, {deepest.x, deepest.y});
  return true;
}
const std::optional<Point2i>& Tracker::inner_point() const { return impl_->state.track().inner; }
void Tracker::set_stop_flag(const std::atomic<bool>* stop) { impl_->stop = stop; }
void Tracker::relearn() {
  impl_->state.mark_across_change();
  if (!impl_->model->relearn()) impl_->state.restart_within_last_box();
}

void Tracker::rescale(int width, int height, int new_width, int new_height) {
  if (width <= 0 || height <= 0 || new_width <= 0 || new_height <= 0) return;
  const double sx = static_cast<double>(new_width) / width;
  const double sy = static_cast<double>(new_height) / height;
  impl_->state.rescale(sx, sy, new_width, new_height);
  if (!impl_->model->rescale(sx, sy, new_width, new_height)) impl_->state.restart_within_last_box();
}

SilhouetteMask Tracker::silhouette() const {
  if (!impl_->state.track().last) return {};
  return impl_->model->silhouette(impl_->width, impl_->height);
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

// Why settings cannot work (empty when they can): said at once, on every frame, never searched
// with. Settings whose single estimate can never fit in the frame's `budget` (millions of rays
// per cast) would end every frame over budget.
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

TrackResult Tracker::Impl::track(const ColorView& frame, EdgeSource& edges, const FrameInput& in) {
  work.budget = WorkBudget(frame_work_limit(frame.luma.width, frame.luma.height, in.tp), stop);
  width = frame.luma.width;
  height = frame.luma.height;
  edges.set_budget(&work.budget);
  TrackResult r = check_and_track(frame, edges, in);
  r.inner_point = state.track().inner;
  r.work = work.budget.spent();
  r.work_limit = work.budget.limit();
  r.gesture = state.pointer.take_gesture();  // whichever transition of the frame made it
  return r;
}

TrackResult Tracker::Impl::check_and_track(const ColorView& frame, EdgeSource& edges,
                                           const FrameInput& in) {
  if (in.trace) in.trace->clear();
  const ImageView& luma = edges.frame();
  if (!luma.valid() || !frame.luma.valid() || frame.luma.width != luma.width ||
      frame.luma.height != luma.height)
    return failed(luma.empty() ? TrackStatus::EmptyImage : TrackStatus::InvalidImage,
                  "no usable frame");
  // The track waits for settings that cannot work to be fixed.
  if (std::string bad = invalid_settings(in, edges.params(), work.budget); !bad.empty())
    return failed(TrackStatus::InvalidParameters, std::move(bad));
  if (work.budget.interrupted()) {  // nothing is started while the stop flag is set
    TrackResult r;
    stopped(Features{}, in.tp, r);
    return r;
  }
  // An edge map given as the frame (EdgeDetector::Input) shows no appearance: the edges model.
  use_model(edges.params().detector == EdgeDetector::Input ? ObjectModelKind::Edges : in.tp.model);
  FrameEvidence ev(frame, edges, work.budget, work.estimator(in.method), in.method, in.params,
                   in.tp, in.trace, work.images);
  return step(ev, in);
}

void Tracker::Impl::use_model(ObjectModelKind k) {
  if (k == kind && model) return;
  state.switch_model();
  model = make_object_model(k);
  kind = k;
}

void Tracker::Impl::forget_object() {
  model->forget(Forget::Everything);
  state.reset();
}

void Tracker::Impl::accept(const Features& f, int width, int height, const FrameInput& in,
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

void Tracker::Impl::refuse(std::string why, const TrackerParams& tp, TrackResult& r,
                           TrackStatus status, bool drop_now) {
  r.status = status;
  r.detail = std::move(why);
  report_last(state, r);
  state.refuse();
  const AfterRefusal next = after_refusal(state.track(), tp, drop_now);
  r.detail += next.note;
  if (!next.drop) return;
  // A track accepted on one frame only was never an object: its model is not searched for.
  model->forget(state.track().accepted > 1 ? Forget::Position : Forget::Everything);
  state.drop();
}

TrackResult Tracker::Impl::not_started(std::string why, bool seeded, const TrackerParams& tp,
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

void Tracker::Impl::stopped(const Features& f, const TrackerParams& tp, TrackResult& r) {
  std::string why = f.detail;
  if (f.status == EstimateStatus::Interrupted || work.budget.interrupted()) {
    // Said here whatever the stage that stopped said: a stop is no budget running out.
    r.status = TrackStatus::Interrupted;
    r.detail = "stopped from outside (the pipeline is stopping or flushing) after " +
               std::to_string(work.budget.spent()) + " work units: the track is kept as it was";
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
