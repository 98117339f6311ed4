#include "projtrack/tracker.hpp"

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstdio>
#include <vector>

#include "acquisition/motion_acquisition.hpp"
#include "acquisition/object_finder.hpp"
#include "appearance/object_model.hpp"
#include "appearance/silhouette_pieces.hpp"
#include "core/mask.hpp"
#include "edges/edge_source.hpp"
#include "pointer/pointer.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/work_budget.hpp"
#include "tracker/edge_region.hpp"
#include "tracker/plausibility.hpp"

namespace projtrack {

// What was Tracker's own: every stage and the state between frames, behind Tracker's pointer so
// that its header needs none of theirs. Tracker's public functions forward here.
struct Tracker::Impl {
  // Tracker's public functions (tracker.hpp).
  void seed(Point2i p);
  void seed_box(const Rect& box);
  void reset();
  const std::optional<Point2i>& inner_point() const { return inner_; }
  void set_stop_flag(const std::atomic<bool>* stop) { stop_ = stop; }
  TrackResult track(const ColorView& frame, const EdgeParams& edge_params, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track(const ImageView& gray, const EdgeParams& edge_params, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track(const ColorView& frame, const ImageView& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track(const ImageView& gray, const ImageView& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);

  // What was Tracker's private part.
  TrackResult track(const ColorView& frame, EdgeSource& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track_frame(const ColorView& frame, EdgeSource& edges, double t, Method m,
                          const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track_edges(const ColorView& frame, EdgeSource& edges, double t, Method m,
                          const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track_appearance(const ColorView& frame, EdgeSource& edges, double t, Method m,
                               const Params& params, const TrackerParams& tp, Trace* trace);
  // The appearance model's first silhouette of an object: around the inner point, where its
  // colours are (an object lost before), or where the frame moves. False and `why` when none.
  bool find_object(const ColorView& frame, EdgeSource& edges, const TrackerParams& tp,
                   bool& resumed, std::string& why);
  // The estimator on the outline of silhouette_, from the inner point (or the silhouette's
  // deepest point when the inner point is not in it).
  Features estimate_on_silhouette(Method m, const Params& params, int width, int height,
                                  Trace* trace);
  Estimator& estimator(Method m);
  // Takes `f` as this frame's estimate; `resumed`: the same object found again after a loss.
  void accept(const Features& f, double t, int width, int height, const TrackerParams& tp,
              bool resumed, TrackResult& r);
  // Refuses this frame's estimate: reports the last accepted one, with `status` (Lost, or
  // OverBudget: no estimate in the frame's work); after `patience` refusals in a row drops the
  // track (the appearance model keeps the object's colours to find it again).
  void refuse(std::string why, const TrackerParams& tp, TrackResult& r,
              TrackStatus status = TrackStatus::Lost);
  // The result of a frame whose work stopped (the budget ran out, or the stop flag) before an
  // estimate: Interrupted keeps the track untouched; OverBudget while tracking is a refusal, and
  // while searching says so.
  void stopped(const Features& f, const TrackerParams& tp, TrackResult& r);
  // Forgets where the object is; `keep_object`: its colours and its first area stay known.
  void drop(bool keep_object);
  // tp's motion and finder parameters with their grey-level thresholds scaled to the scene's
  // contrast (TrackerParams::full_contrast), as the last frame compared showed it.
  MotionDetector::Params motion_params(const TrackerParams& tp) const;
  FinderParams finder_params(const TrackerParams& tp) const;

  EdgeMap edge_map_;
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators_;  // made on first use
  WorkBudget budget_;  // this frame's: every estimate spends from it
  const std::atomic<bool>* stop_ = nullptr;
  std::optional<Point2i> inner_;
  std::optional<Rect> box_;  // the box a track was seeded with, until it starts
  std::optional<Features> last_good_;
  Point2d velocity_;  // of the centroid between the last two accepted frames, px per frame
  int refused_in_a_row_ = 0;
  std::uint32_t recent_refusals_ = 0;  // a bit per frame since the track started, newest lowest
  Pointer pointer_;
  ObjectModelKind model_ = ObjectModelKind::Appearance;

  // Edges model.
  MotionAcquisition acquisition_;

  // Appearance model.
  ObjectModel object_;
  ObjectFinder finder_;
  MotionDetector motion_;
  MotionDetector::Motion moved_;
  MotionDetector::Motion moved_before_;  // of the last frame before this one that showed motion
  Mask silhouette_, first_;
  SilhouettePieces pieces_;
  Trace piece_trace_;
  bool split_ = false;  // estimate_on_silhouette() cuts the silhouette into pieces
  MaskOps ops_;
  std::vector<std::uint8_t> barrier_;
  double lost_area_ = 0;  // the object's area and centroid when it was lost
  Point2d lost_centroid_;
  int searched_ = 0;     // frames searched by colour since the loss
  bool seeded_ = false;  // the track started from the user's point or box
  int still_ = 0;        // frames in a row the object has not moved
  Exposure exposure_;    // how the appearance model reads frames (TrackerParams::dim_white)
};

Tracker::Tracker() : impl_(std::make_unique<Impl>()) {}
Tracker::~Tracker() = default;
Tracker::Tracker(Tracker&&) noexcept = default;
Tracker& Tracker::operator=(Tracker&&) noexcept = default;

void Tracker::seed(Point2i p) { impl_->seed(p); }
void Tracker::seed_box(const Rect& box) { impl_->seed_box(box); }
void Tracker::reset() { impl_->reset(); }
const std::optional<Point2i>& Tracker::inner_point() const { return impl_->inner_point(); }
void Tracker::set_stop_flag(const std::atomic<bool>* stop) { impl_->set_stop_flag(stop); }

TrackResult Tracker::track(const ColorView& frame, const EdgeParams& edge_params, double t,
                           Method m, const Params& params, const TrackerParams& tp, Trace* trace) {
  return impl_->track(frame, edge_params, t, m, params, tp, trace);
}
TrackResult Tracker::track(const ImageView& gray, const EdgeParams& edge_params, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  return impl_->track(gray, edge_params, t, m, params, tp, trace);
}
TrackResult Tracker::track(const ColorView& frame, const ImageView& edges, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  return impl_->track(frame, edges, t, m, params, tp, trace);
}
TrackResult Tracker::track(const ImageView& gray, const ImageView& edges, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  return impl_->track(gray, edges, t, m, params, tp, trace);
}

void Tracker::Impl::seed(Point2i p) {
  reset();
  inner_ = p;
}

void Tracker::Impl::seed_box(const Rect& box) {
  reset();
  inner_ = Point2i{box.x + box.width / 2, box.y + box.height / 2};
  box_ = box;
}

void Tracker::Impl::reset() {
  drop(false);
  acquisition_.reset();
}

void Tracker::Impl::drop(bool keep_object) {
  if (last_good_) {
    lost_area_ = last_good_->area;
    lost_centroid_ = last_good_->centroid;
  }
  inner_.reset();
  box_.reset();
  last_good_.reset();
  refused_in_a_row_ = 0;
  recent_refusals_ = 0;
  pointer_.interrupt();
  searched_ = 0;
  motion_.reset();
  moved_ = {};
  moved_before_ = {};
  if (keep_object) {
    object_.lose();
  } else {
    object_.reset();
    pointer_.reset();
  }
}

Estimator& Tracker::Impl::estimator(Method m) {
  auto& e = estimators_[static_cast<int>(m)];
  if (!e) e = method_info(m).make();
  return *e;
}

void Tracker::Impl::accept(const Features& f, double t, int width, int height,
                           const TrackerParams& tp, bool resumed, TrackResult& r) {
  if (!last_good_) {  // a track (re)starts here
    seeded_ = inner_.has_value() && !resumed;
    still_ = 0;
    if (resumed && pointer_.started())
      pointer_.resume();
    else
      pointer_.start(f.area);
    r.acquired = true;
  }
  velocity_ = last_good_ ? Point2d{f.centroid.x - last_good_->centroid.x,
                                   f.centroid.y - last_good_->centroid.y}
                         : Point2d{0, 0};
  inner_ = f.inner_point;
  box_.reset();
  last_good_ = f;
  refused_in_a_row_ = 0;
  recent_refusals_ <<= 1;
  pointer_.update(f, width, height, t, tp);
  r.status = reported_status(f.status);
  r.features = f;
  r.has_pose = true;
  r.pose = pointer_.pose();
  r.raw_pose = pointer_.raw();
  r.push = pointer_.pushed();
}

namespace {

double contrast(int spread, const TrackerParams& tp) {
  if (spread <= 0 || !(tp.full_contrast > 0)) return 1.0;
  return std::clamp(spread / tp.full_contrast, 1.0 / 3, 1.0);
}

}  // namespace

MotionDetector::Params Tracker::Impl::motion_params(const TrackerParams& tp) const {
  MotionDetector::Params p = tp.motion;
  p.threshold = static_cast<int>(std::lround(p.threshold * contrast(motion_.spread(), tp)));
  return p;
}

FinderParams Tracker::Impl::finder_params(const TrackerParams& tp) const {
  FinderParams p = tp.finder;
  p.background_change =
      static_cast<int>(std::lround(p.background_change * contrast(motion_.spread(), tp)));
  return p;
}

void Tracker::Impl::refuse(std::string why, const TrackerParams& tp, TrackResult& r,
                           TrackStatus status) {
  ++refused_in_a_row_;
  recent_refusals_ = (recent_refusals_ << 1) | 1u;
  r.status = status;
  r.detail = std::move(why);
  // Only an accepted estimate is ever reported: with none yet, no features at all.
  r.features = last_good_ ? *last_good_ : Features{};
  r.has_pose = last_good_.has_value();
  r.pose = pointer_.pose();
  r.raw_pose = pointer_.raw();
  pointer_.interrupt();
  const int window = std::min(2 * tp.unsteady, 31);
  const bool unsteady =
      model_ == ObjectModelKind::Appearance && !seeded_ && tp.unsteady > 0 &&
      refused_in_a_row_ == 1 &&
      static_cast<int>(std::bitset<32>(recent_refusals_ & ((1u << window) - 1)).count()) >=
          tp.unsteady;
  if (unsteady) r.detail += "; refused on and off: an unsteady fragment, not an object";
  if (refused_in_a_row_ > tp.patience || unsteady) {
    r.detail += "; the track is dropped";
    const bool appearance = model_ == ObjectModelKind::Appearance;
    drop(appearance);
    if (!appearance) acquisition_.reset();
  }
}

TrackResult Tracker::Impl::track(const ColorView& frame, const EdgeParams& edge_params, double t,
                                 Method m, const Params& params, const TrackerParams& tp,
                                 Trace* trace) {
  EdgeSource edges(edge_map_, frame.luma, edge_params);
  return track(frame, edges, t, m, params, tp, trace);
}

TrackResult Tracker::Impl::track(const ImageView& gray, const EdgeParams& edge_params, double t,
                                 Method m, const Params& params, const TrackerParams& tp,
                                 Trace* trace) {
  return track(ColorView{gray, {}, {}}, edge_params, t, m, params, tp, trace);
}

TrackResult Tracker::Impl::track(const ColorView& frame, const ImageView& edges, double t, Method m,
                                 const Params& params, const TrackerParams& tp, Trace* trace) {
  EdgeSource given(edges);
  return track(frame, given, t, m, params, tp, trace);
}

TrackResult Tracker::Impl::track(const ImageView& gray, const ImageView& edges, double t, Method m,
                                 const Params& params, const TrackerParams& tp, Trace* trace) {
  return track(ColorView{gray, {}, {}}, edges, t, m, params, tp, trace);
}

TrackResult Tracker::Impl::track(const ColorView& frame, EdgeSource& edges, double t, Method m,
                                 const Params& params, const TrackerParams& tp, Trace* trace) {
  budget_ = WorkBudget(frame_work_limit(frame.luma.width, frame.luma.height, tp), stop_);
  edges.set_budget(&budget_);
  TrackResult r = track_frame(frame, edges, t, m, params, tp, trace);
  r.inner_point = inner_;
  r.work = budget_.spent();
  r.work_limit = budget_.limit();
  return r;
}

void Tracker::Impl::stopped(const Features& f, const TrackerParams& tp, TrackResult& r) {
  std::string why = f.detail;
  if (f.status == EstimateStatus::Interrupted || budget_.interrupted()) {
    r.status = TrackStatus::Interrupted;
    r.detail = why.empty() ? "stopped: the work was interrupted" : std::move(why);
    r.features = last_good_ ? *last_good_ : Features{};
    r.has_pose = last_good_.has_value();
    r.pose = pointer_.pose();
    r.raw_pose = pointer_.raw();
    return;
  }
  if (why.empty()) why = "the frame's work budget ran out";
  if (inner_ || last_good_) {
    refuse(std::move(why), tp, r, TrackStatus::OverBudget);
    return;
  }
  r.status = TrackStatus::OverBudget;  // searching: the next frame searches again
  r.detail = std::move(why);
}

TrackResult Tracker::Impl::track_frame(const ColorView& frame, EdgeSource& edges, double t,
                                       Method m, const Params& params, const TrackerParams& tp,
                                       Trace* trace) {
  if (trace) trace->clear();
  const ImageView& luma = edges.frame();
  if (!luma.valid() || !frame.luma.valid() || frame.luma.width != luma.width ||
      frame.luma.height != luma.height) {
    TrackResult r;
    r.status = luma.empty() ? TrackStatus::EmptyImage : TrackStatus::InvalidImage;
    r.detail = "no usable frame";
    return r;
  }
  // Settings that cannot work are said at once, on every frame, never searched with: the track
  // waits for them to be fixed.
  std::string bad = validate(params);
  if (bad.empty()) bad = validate(edges.params());
  if (bad.empty() && !(tp.max_work >= 0 && tp.max_work <= kMaxMaxWork))
    bad = "max_work = " + std::to_string(tp.max_work) + " is outside [0, " +
          std::to_string(kMaxMaxWork) + "]";
  // Settings whose single estimate can never fit in the frame's budget (millions of rays per
  // cast) would end every frame over budget: said at once instead.
  if (const std::uint64_t least = least_estimate_cost(m, params);
      bad.empty() && least > budget_.limit()) {
    bad = "one estimate with rays = " + std::to_string(params.rays) +
          (method_info(m).reads & kReadsRecursion
               ? " and recursion = " + std::to_string(params.recursion)
               : std::string()) +
          " costs at least " + std::to_string(least) +
          " work units, more than the frame's budget of " + std::to_string(budget_.limit()) +
          " (max_work = " + std::to_string(tp.max_work) +
          " × its pixels): fewer rays or levels, or a larger max_work";
  }
  if (!bad.empty()) {
    TrackResult r;
    r.status = TrackStatus::InvalidParameters;
    r.detail = std::move(bad);
    return r;
  }
  if (budget_.interrupted()) {  // nothing is started while the stop flag is set
    TrackResult r;
    stopped(Features{}, tp, r);
    return r;
  }
  // An edge map given as the frame (EdgeDetector::Input) shows no appearance: the edges model.
  const ObjectModelKind model =
      edges.params().detector == EdgeDetector::Input ? ObjectModelKind::Edges : tp.model;
  if (model != model_) {  // another model: the same object, found again its own way
    const std::optional<Point2i> inner = inner_;
    reset();
    inner_ = inner;
    model_ = model;
  }
  return model_ == ObjectModelKind::Edges ? track_edges(frame, edges, t, m, params, tp, trace)
                                          : track_appearance(frame, edges, t, m, params, tp, trace);
}

// ---- The edges model: the paper's tracker ----------------------------------------------------

TrackResult Tracker::Impl::track_edges(const ColorView& frame, EdgeSource& edges, double t,
                                       Method m, const Params& params, const TrackerParams& tp,
                                       Trace* trace) {
  TrackResult r;
  const int w = frame.luma.width, h = frame.luma.height;
  const Features* last = last_good_ ? &*last_good_ : nullptr;
  const double limit = area_limit(w, h, tp, last);
  if (!inner_) {
    const ImageView all = edges.region({0, 0, w, h});
    std::optional<Features> f =
        acquisition_.acquire(frame.luma, all, estimator(m), params, limit, tp, budget_, r.detail);
    if (!f) {
      if (budget_.ran_out() || budget_.interrupted()) {
        Features none;
        none.detail = std::move(r.detail);
        stopped(none, tp, r);
        return r;
      }
      r.status = tp.acquisition == Acquisition::Manual ? TrackStatus::NoInnerPoint
                                                       : TrackStatus::Searching;
      return r;
    }
    r.detail.clear();
    accept(*f, t, w, h, tp, false, r);
    return r;
  }
  EstimateOptions limited;
  limited.area_limit = limit;
  limited.budget = &budget_;
  const Features f =
      estimate_in_region(edges, estimator(m), m, *inner_, last ? &last->bbox : nullptr, velocity_,
                         params, limited, tp, trace);
  if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
    stopped(f, tp, r);
    return r;
  }
  // Not the object's doing: say what is wrong, keep the track.
  if (f.status == EstimateStatus::InvalidParameters || f.status == EstimateStatus::InvalidImage ||
      f.status == EstimateStatus::EmptyImage) {
    r.status = reported_status(f.status);
    r.features = f;
    return r;
  }
  std::string why = refused(f, w, h, tp, last, limit);
  if (why.empty())
    accept(f, t, w, h, tp, false, r);
  else
    refuse(std::move(why), tp, r);
  return r;
}

// ---- The appearance model: real footage -------------------------------------------------------

bool Tracker::Impl::find_object(const ColorView& frame, EdgeSource& edges, const TrackerParams& tp,
                                bool& resumed, std::string& why) {
  const int w = frame.luma.width, h = frame.luma.height;
  const FinderParams fp = finder_params(tp);
  Point2i seed{w / 2, h / 2};
  bool found = false;
  resumed = false;
  if (inner_) {
    seed = *inner_;
    if (!Rect{0, 0, w, h}.contains(seed)) {
      why = "the inner point lies outside the frame";
      return false;
    }
    found = box_ ? finder_.from_box(frame, *box_, fp, first_, why)
                 : finder_.from_seed(frame, seed, fp, first_, why);
  } else if (tp.acquisition == Acquisition::Center) {
    found = finder_.from_seed(frame, seed, fp, first_, why);
    if (!found) why = "at the frame centre: " + why;
  } else {  // Auto: an object lost before by its colours; else whatever moves
    // The last frame that showed motion, for the finder's check that what moves now moved then
    // too (a frame repeated by the camera or the encoder shows none, and does not count).
    if (moved_.fraction >= tp.min_motion) std::swap(moved_before_, moved_);
    if (!motion_.update(frame.luma, motion_params(tp), moved_)) {
      why = "waiting for a second frame to compare";
      return false;
    }
    if (moved_.fraction < tp.min_motion) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "waiting for motion (%.2g %% of the frame changed)",
                    100 * moved_.fraction);
      why = buf;
      return false;
    }
    if (object_.knows_colours() && searched_ >= tp.forget_after) {
      object_.reset();  // not seen for long: look for any object
      pointer_.reset();
    }
    ++searched_;
    if (object_.knows_colours()) {
      found = finder_.from_model(frame, object_.appearance(), moved_, lost_area_, tp.leak_factor,
                                 lost_centroid_, fp, first_, seed, why);
      resumed = found;
    } else {
      found = finder_.from_motion(frame, moved_, moved_before_, fp, first_, seed, why);
    }
  }
  if (!found) return false;
  const int scale = finder_.scale();
  const bool ok = resumed
                      ? object_.resume(frame, edges, first_, scale, seed, tp.object, silhouette_)
                      : object_.start(frame, edges, first_, scale, seed, finder_.border_colours(),
                                      tp.object, silhouette_);
  if (!ok) {
    why = "nothing of the object's colours is left around it";
    return false;
  }
  // An object found by motion was wholly in view: a silhouette that grew from it to the frame's
  // border has run into the arm that holds it (or the table), and is no start.
  if (!inner_ && !resumed) {
    const Rect b = to_frame(moments(silhouette_).bbox, object_.scale(), w, h);
    if (b.x <= 0 || b.y <= 0 || b.right() >= w || b.bottom() >= h) {
      object_.reset();
      why = "what moved there runs into the frame's border (an arm, not an object): left alone";
      return false;
    }
  }
  // An object found by motion alone must not be the background: a static region that a
  // passer-by's colours joined is left alone, whatever moved around it.
  if (!inner_ && !resumed &&
      finder_.foreground_share(silhouette_, object_.scale(), fp) < fp.min_foreground) {
    object_.reset();
    why = "what moved there is the background (a static region): left alone";
    return false;
  }
  return true;
}

Features Tracker::Impl::estimate_on_silhouette(Method m, const Params& params, int width,
                                               int height, Trace* trace) {
  // The silhouette's outline is closed: there is no leak to stop (no area limit) and no gap to
  // tolerate (a narrow neck of the object is not a break in its contour).
  EstimateOptions closed;
  closed.closed_outline = true;
  closed.budget = &budget_;
  // One estimate per piece, each at full resolution on its piece alone as an edge map (every
  // pixel out of it is an edge), with one pixel of margin so that fills stop at it and rays end
  // on it; the largest piece first, from the track's inner point when it is in it; the features
  // add up. The pieces are found at the object model's work scale.
  const int s = object_.scale();
  // Usually one estimate covers the silhouette; only when it covers much less than the
  // silhouette's pixels is it cut into pieces (a neck or a finger kept the estimate out).
  const int n = split_ ? pieces_.split(silhouette_, std::max(1, params.grid_size / (2 * s)), 0.03)
                       : pieces_.whole(silhouette_);
  const Rect r = clip_to_frame(
      [&] {
        Rect f = to_frame(silhouette_.rect(), s, width, height);
        return Rect{f.x - 1, f.y - 1, f.width + 2, f.height + 2};
      }(),
      width, height);
  const auto work_of = [s](int v) { return v < 0 ? -1 : v / s; };
  Features total;
  double sx = 0, sy = 0;
  BoundsAccumulator box, reach;
  for (int k = 0; k < n; ++k) {
    const Mask& piece = pieces_.piece(k);
    // Each work pixel of the piece clears its s×s block of frame pixels.
    const std::size_t barrier = static_cast<std::size_t>(r.width) * r.height;
    if (budget_.exhausted(clearing_cost(barrier))) {  // no work left to lay this piece out
      Features none;
      none.status =
          budget_.interrupted() ? EstimateStatus::Interrupted : EstimateStatus::OverBudget;
      none.detail = "the work budget ran out: " + std::to_string(budget_.spent()) + " of " +
                    std::to_string(budget_.limit()) + " units spent, before piece " +
                    std::to_string(k + 1) + " of the silhouette";
      return none;
    }
    budget_.spend(clearing_cost(barrier));
    barrier_.assign(barrier, 255);
    const Rect& pr = piece.rect();
    for (int wy = 0; wy < pr.height; ++wy) {
      const std::uint8_t* in = piece.row(wy);
      const int y0 = std::max(r.y, (pr.y + wy) * s), y1 = std::min(r.bottom(), (pr.y + wy + 1) * s);
      for (int wx = 0; wx < pr.width; ++wx) {
        if (!in[wx]) continue;
        int run = wx;
        while (run + 1 < pr.width && in[run + 1]) ++run;
        const int x0 = std::max(r.x, (pr.x + wx) * s),
                  x1 = std::min(r.right(), (pr.x + run + 1) * s);
        for (int y = y0; y < y1 && x0 < x1; ++y)
          std::fill_n(barrier_.data() + static_cast<std::size_t>(y - r.y) * r.width + (x0 - r.x),
                      x1 - x0, 0);
        wx = run;
      }
    }
    Point2i start;
    if (k == 0 && inner_ && pieces_.piece_at({work_of(inner_->x), work_of(inner_->y)}) == 0) {
      start = *inner_;
    } else {
      const Point2i deep = pieces_.deepest(k);
      start = {deep.x * s + s / 2, deep.y * s + s / 2};
    }
    Trace* t = k == 0 ? trace : (trace ? &piece_trace_ : nullptr);
    Features f = estimator(m).estimate(ImageView(barrier_.data(), r.width, r.height, r.width),
                                       {start.x - r.x, start.y - r.y}, params, closed, t);
    translate(f, r.x, r.y);
    if (t) t->translate(r.x, r.y);
    if (t && t != trace) trace->append(*t);
    if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted)
      return f;  // no estimate of the whole silhouette
    if (!f.valid()) {
      if (k == 0) return f;  // the estimator's own failure: say what it was
      continue;
    }
    if (k == 0) {
      total = f;
    } else {
      total.area += f.area;
      total.iterations = std::max(total.iterations, f.iterations);
      total.rays_cast += f.rays_cast;
      total.pixels_visited += f.pixels_visited;
    }
    sx += f.area * f.centroid.x;
    sy += f.area * f.centroid.y;
    box.add(f.bbox);
    reach.add(f.reach);
  }
  // (A fill that covers much less than the silhouette was kept out of part of it; rays always
  // see less of a shape that is not star-shaped around the inner point, and are left so.)
  if (n == 1 && total.valid() && !split_ && method_info(m).family == Family::Fill &&
      total.area < 0.8 * moments(silhouette_).area * s * s) {
    split_ = true;  // once more, in pieces
    total = estimate_on_silhouette(m, params, width, height, trace);
    split_ = false;
    return total;
  }
  if (n == 0) {
    total.status = EstimateStatus::EmptyImage;
    total.detail = "the silhouette is empty";
    return total;
  }
  if (total.area > 0) total.centroid = {sx / total.area, sy / total.area};
  total.bbox = box.rect();
  total.reach = reach.rect();
  if (trace) {  // the outline at full resolution: pixels in, with a 4-neighbour out
    trace->outline.clear();
    const auto in = [&](int x, int y) { return silhouette_.at({work_of(x), work_of(y)}); };
    for (int y = r.y; y < r.bottom(); ++y)
      for (int x = r.x; x < r.right(); ++x)
        if (in(x, y) && (!in(x - 1, y) || !in(x + 1, y) || !in(x, y - 1) || !in(x, y + 1)))
          trace->outline.push_back({x, y});
  }
  if (total.valid()) total.status = border_status(total.bbox, width, height);
  return total;
}

TrackResult Tracker::Impl::track_appearance(const ColorView& raw, EdgeSource& edges, double t,
                                            Method m, const Params& params, const TrackerParams& tp,
                                            Trace* trace) {
  TrackResult r;
  // The frame as the appearance model reads it: a dim one stretched to a normal exposure. The
  // model's colours are learned under it, so it is measured only while no object is known and
  // held while one is: the frame's range changes with what moves through it (a bright object
  // that leaves a dim room), and the model follows slow changes of the light by itself.
  if (!object_.knows_colours())
    exposure_ = exposure_for(luma_range(raw.luma), tp.dim_white, tp.full_contrast);
  ColorView frame = raw;
  frame.exposure = exposure_;
  const int w = frame.luma.width, h = frame.luma.height;
  if (!object_.tracking()) {
    if (!inner_ && tp.acquisition == Acquisition::Manual) {
      r.status = TrackStatus::NoInnerPoint;
      r.detail = "no inner point: set one, or click in the video";
      return r;
    }
    bool resumed = false;
    std::string why;
    const bool seeded = inner_.has_value();
    if (find_object(frame, edges, tp, resumed, why)) {
      const Features f = estimate_on_silhouette(m, params, w, h, trace);
      if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
        object_.lose();
        stopped(f, tp, r);
        return r;
      }
      why = implausible(f, w, h, tp);
      if (why.empty()) {
        accept(f, t, w, h, tp, resumed, r);
        searched_ = 0;
        return r;
      }
      object_.lose();
    } else if (budget_.ran_out() || budget_.interrupted()) {  // its edges were cut short
      stopped(Features{}, tp, r);
      return r;
    }
    if (seeded) {  // the user's point: keep trying it for a while, as a refused estimate
      refuse(std::move(why), tp, r);
      return r;
    }
    r.status = TrackStatus::Searching;
    r.detail = std::move(why);
    return r;
  }
  const Point2i hint = inner_ ? *inner_ : Point2i{-1, -1};
  if (!object_.find(frame, edges, velocity_, hint, tp.object, silhouette_)) {
    if (budget_.ran_out() || budget_.interrupted())  // its edges were cut short
      stopped(Features{}, tp, r);
    else
      refuse("nothing of the object's colours is left where it was", tp, r);
    return r;
  }
  const Features f = estimate_on_silhouette(m, params, w, h, trace);
  if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
    stopped(f, tp, r);
    return r;
  }
  std::string why = refused(f, w, h, tp, last_good_ ? &*last_good_ : nullptr, HUGE_VAL);
  if (!why.empty()) {
    refuse(std::move(why), tp, r);
    return r;
  }
  // An object found without the user's point that the scene's background holds — its silhouette
  // the same as what the finder saw there while it searched, and its box not moving — is not
  // reported as measured on that frame (held, as a refused estimate), and is dropped after
  // `still_frames` such frames in a row: a static region that motion around it picked (the
  // original system dropped an object that stopped moving). One the user pointed at is kept,
  // whatever it is.
  if (!seeded_ && tp.still_frames > 0) {
    // Almost none of its box changed since the last frame (compared on every frame, so that the
    // previous one is the last frame)...
    const FinderParams fp = finder_params(tp);
    bool background = motion_.update(frame.luma, motion_params(tp), moved_);
    if (background) {
      std::size_t inside = 0;
      for (const Point2i& q : moved_.points) inside += f.bbox.contains(q);
      background = static_cast<double>(inside) * moved_.step * moved_.step <
                   fp.min_moving * f.bbox.width * f.bbox.height;
    }
    // ... and on this frame its silhouette is what the background holds there.
    background = background && finder_.foreground_share(frame, silhouette_, object_.scale(), fp) <
                                   fp.min_foreground;
    still_ = background ? still_ + 1 : 0;
    if (still_ >= tp.still_frames) {
      still_ = 0;
      refused_in_a_row_ = tp.patience;  // dropped now
      refuse("the object is part of the scene's background: a static region", tp, r);
      return r;
    }
    if (still_ > 0) {
      refuse("the object does not move and looks like the scene's background", tp, r);
      return r;
    }
  }
  object_.accept(silhouette_, tp.object);
  accept(f, t, w, h, tp, false, r);
  return r;
}

}  // namespace projtrack
