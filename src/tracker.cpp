#include "tracker.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace projtrack {

namespace {

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g %%", 100 * fraction);
  return buf;
}

double share_inside(const std::vector<Point2i>& points, const Rect& r) {
  if (points.empty()) return 0;
  std::size_t n = 0;
  for (const Point2i& p : points)
    n += p.x >= r.x && p.y >= r.y && p.x < r.right() && p.y < r.bottom();
  return static_cast<double>(n) / points.size();
}

}  // namespace

ImageView EdgeSource::region(const Rect& r) {
  if (map_) return map_->detect(gray_, params_, r);
  const ImageView& f = given_;
  const int x0 = std::clamp(r.x, 0, f.width), y0 = std::clamp(r.y, 0, f.height);
  const int x1 = std::clamp(r.right(), x0, f.width), y1 = std::clamp(r.bottom(), y0, f.height);
  if (!f.valid() || x1 <= x0 || y1 <= y0) return {};
  return ImageView(f.row(y0) + x0, x1 - x0, y1 - y0, f.stride);
}

void Tracker::seed(Point2i p) {
  reset();
  inner_ = p;
}

void Tracker::reset() {
  inner_.reset();
  last_good_.reset();
  area0_ = 0;
  refused_in_a_row_ = 0;
  push_.reset();
  motion_.reset();
}

Estimator& Tracker::estimator(Method m) {
  auto& e = estimators_[static_cast<int>(m)];
  if (!e) e = make_estimator(m);
  return *e;
}

double Tracker::area_limit(const ImageView& frame, const Params& params,
                           const TrackerParams& tp) const {
  // Just above what would be refused anyway: a larger estimate is a leak, whatever its size.
  double limit = std::max(tp.max_area, 0.0) * frame.width * frame.height;
  if (last_good_ && tp.leak_factor > 0) limit = std::min(limit, tp.leak_factor * last_good_->area);
  limit = std::isfinite(limit) ? std::min(std::floor(limit) + 1, kMaxAreaLimit) : kMaxAreaLimit;
  return params.area_limit > 0 ? std::min(limit, params.area_limit) : limit;
}

std::string Tracker::implausible(const Features& f, const ImageView& edges,
                                 const TrackerParams& tp) const {
  if (!f.valid()) return f.detail.empty() ? std::string(status_name(f.status)) : f.detail;
  const double frame = static_cast<double>(edges.width) * edges.height;
  if (f.status == Status::CoversFrame)
    return "the estimate covers the frame (a leak, or no closed contour around the inner point)";
  if (f.area > tp.max_area * frame)
    return "the estimate covers " + percent(f.area / frame) + " of the frame (a leak)";
  if (f.area < tp.min_area * frame)
    return "the estimate is too small (" + percent(f.area / frame) + " of the frame)";
  return {};
}

std::string Tracker::refused(const Features& f, const ImageView& edges,
                             const TrackerParams& tp) const {
  std::string why = implausible(f, edges, tp);
  if (!why.empty() || !last_good_) return why;
  const double ratio = f.area / last_good_->area;
  char buf[96];
  if (ratio > tp.leak_factor) {
    if (f.area > limit_)
      std::snprintf(buf, sizeof buf, "the area passed %.1f× the last frame's: a leak, not filled",
                    tp.leak_factor);
    else
      std::snprintf(buf, sizeof buf, "the area jumped %.1f× since the last frame (a leak)", ratio);
    return buf;
  }
  if (ratio < 1 / tp.leak_factor) {
    std::snprintf(buf, sizeof buf, "the area shrank to %.2f× of the last frame's", ratio);
    return buf;
  }
  return {};
}

std::optional<Features> Tracker::acquire(const ImageView& gray, const ImageView& edges, Method m,
                                         const Params& params, const TrackerParams& tp,
                                         std::string& why) {
  Estimator& est = estimator(m);
  // Motion history from before a switch of mode (or from the last search) is stale.
  if (tp.acquisition != last_acquisition_) motion_.reset();
  last_acquisition_ = tp.acquisition;
  if (tp.acquisition == Acquisition::Manual) {
    why = "no inner point: set one, or click in the video";
    return std::nullopt;
  }
  if (tp.acquisition == Acquisition::Center) {
    Features f = est.estimate(edges, {edges.width / 2, edges.height / 2}, params);
    why = implausible(f, edges, tp);
    if (why.empty()) return f;
    why = "at the frame centre: " + why;
    return std::nullopt;
  }
  if (!motion_.update(gray, tp.motion, moved_)) {
    why = "waiting for a second frame to compare";
    return std::nullopt;
  }
  if (moved_.fraction < tp.min_motion) {
    why = "waiting for motion (" + percent(moved_.fraction) + " of the frame changed)";
    return std::nullopt;
  }
  std::vector<Point2i> candidates{round_to_pixel(moved_.centroid)};
  if (tp.strategy == AutoAcquisition::CompactMovingRegion) {
    const std::size_t n = moved_.points.size(), k = std::max(1, tp.candidates);
    for (std::size_t i = 0; i < k && i < n; ++i) candidates.push_back(moved_.points[i * n / k]);
  }
  std::optional<Features> best;
  double best_score = -1;
  Params limited = params;
  limited.area_limit = area_limit(edges, params, tp);
  for (const Point2i& c : candidates) {
    if (best && c.x >= best->bbox.x && c.y >= best->bbox.y && c.x < best->bbox.right() &&
        c.y < best->bbox.bottom())
      continue;  // already inside the best region found
    Features f = est.estimate(edges, c, limited);
    if (!implausible(f, edges, tp).empty()) continue;
    // A sliver between two edges (seen on real footage: a 2×23 px strip) is not an object.
    if (std::min(f.bbox.width, f.bbox.height) < tp.min_acquired_side) continue;
    if (tp.strategy == AutoAcquisition::MotionCentroid) return f;
    // Moving (holds changed pixels) and compact (fills its box), unlike a background region.
    const double box = static_cast<double>(f.bbox.width) * f.bbox.height;
    const double score = share_inside(moved_.points, f.bbox) * f.area / box;
    if (score > best_score) {
      best_score = score;
      best = std::move(f);
    }
  }
  if (!best)
    why = "no closed region where the frame moved (" + std::to_string(candidates.size()) +
          " seeds tried)";
  return best;
}

void Tracker::accept(const Features& f, double t, const ImageView& edges, const TrackerParams& tp,
                     TrackResult& r) {
  if (!last_good_) {  // a new track: depth 1 here, fresh filters
    area0_ = f.area;
    fx_.reset();
    fy_.reset();
    fdepth_.reset();
    push_.reset();
    r.acquired = true;
  }
  velocity_ = last_good_ ? Point2d{f.centroid.x - last_good_->centroid.x,
                                   f.centroid.y - last_good_->centroid.y}
                         : Point2d{0, 0};
  inner_ = f.inner_point;
  last_good_ = f;
  refused_in_a_row_ = 0;
  raw_pose_ = {2 * (f.centroid.x + 0.5) / edges.width - 1,
               2 * (f.centroid.y + 0.5) / edges.height - 1,
               area0_ > 0 ? std::sqrt(f.area / area0_) : 1.0};
  if (tp.smoothing) {
    fx_.set_params(tp.filter);
    fy_.set_params(tp.filter);
    fdepth_.set_params(tp.filter);
    pose_ = {fx_.filter(raw_pose_.x, t), fy_.filter(raw_pose_.y, t),
             fdepth_.filter(raw_pose_.depth, t)};
  } else {
    pose_ = raw_pose_;
  }
  push_.set_params(tp.push);
  r.push = push_.update(raw_pose_.depth, t);
  r.status = f.status;
  r.features = f;
  r.has_pose = true;
  r.pose = pose_;
  r.raw_pose = raw_pose_;
}

TrackResult Tracker::track(const ImageView& gray, const EdgeParams& edge_params, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  EdgeSource edges(edge_map_, gray, edge_params);
  return track(gray, edges, t, m, params, tp, trace);
}

TrackResult Tracker::track(const ImageView& gray, const ImageView& edges, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  EdgeSource given(edges);
  return track(gray, given, t, m, params, tp, trace);
}

namespace {

// `box` grown by `margin` on every side, clipped to the frame and anchored on the block grid (so
// rasterized ray-casting's blocks line up with the frame's).
Rect grown(const Rect& box, int margin, int block_size, const ImageView& frame) {
  const int bs = std::max(1, block_size);
  int x0 = std::max(0, box.x - margin), y0 = std::max(0, box.y - margin);
  const int x1 = std::min(frame.width, box.right() + margin);
  const int y1 = std::min(frame.height, box.bottom() + margin);
  x0 -= x0 % bs;
  y0 -= y0 % bs;
  return {x0, y0, x1 - x0, y1 - y0};
}

Rect united(const Rect& a, const Rect& b) {
  const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  return {x0, y0, std::max(a.right(), b.right()) - x0, std::max(a.bottom(), b.bottom()) - y0};
}

bool holds(const Rect& r, Point2i p) {
  return r.x <= p.x && p.x < r.right() && r.y <= p.y && p.y < r.bottom();
}

}  // namespace

Features Tracker::estimate_around(EdgeSource& edges, Method m, const Params& params,
                                  const TrackerParams& tp, Trace* trace) {
  const ImageView& frame = edges.frame();
  const Rect whole{0, 0, frame.width, frame.height};
  Rect region = whole;
  int margin = 0;
  Params limited = params;
  limited.area_limit = limit_ = area_limit(frame, params, tp);
  if (tp.edge_margin >= 0 && last_good_) {
    // The last box and where it would be if it kept its last motion, with a margin around both.
    const Rect& b = last_good_->bbox;
    const Rect ahead{b.x + static_cast<int>(std::lround(velocity_.x)),
                     b.y + static_cast<int>(std::lround(velocity_.y)), b.width, b.height};
    const double grown_by = tp.edge_margin * std::max(b.width, b.height);
    margin = std::max(16, static_cast<int>(std::min(grown_by, 1e6)));
    // Gap-tolerant filling reads a band of max_gap + 2 px beside its lines, beyond the box.
    if (m == Method::GapTolerantFilling) margin += params.max_gap + 2;
    const Rect r = grown(united(b, ahead), margin, params.block_size, frame);
    if (holds(r, *inner_)) region = r;
  }
  for (int growths = 0;; ++growths) {
    const ImageView e = edges.region(region);
    Features f =
        estimator(m).estimate(e, {inner_->x - region.x, inner_->y - region.y}, limited, trace);
    translate(f, region.x, region.y);
    if (trace) trace->translate(region.x, region.y);
    if (!f.valid()) return f;
    // Reaching the region's edge (where it is not the frame's) means the region cut the estimate:
    // redo it on a larger region, so that the answer does not depend on the region. (Except
    // through Canny's hysteresis, which is not local: a weak edge joined to a strong one only
    // outside the region is missing inside it. docs/tracker.md says so.)
    // Edges within a few pixels of an inner border may differ from the frame's (later filter
    // passes replicate the region's border), so coming that close counts as being cut too.
    const int g = edges.border_guard();
    const Rect& b = f.reach;
    const bool cut = (b.x <= region.x + g && region.x > 0) ||
                     (b.y <= region.y + g && region.y > 0) ||
                     (b.right() >= region.right() - g && region.right() < frame.width) ||
                     (b.bottom() >= region.bottom() - g && region.bottom() < frame.height);
    // A fill stopped at the limit and not cut by the region is refused anyway: no regrowing.
    if (!cut || region == whole) {
      f.status = border_status(f.bbox, frame.width, frame.height);
      return f;
    }
    // First around the cut estimate with four times the margin (a fast or growing object), then
    // the whole frame (a leak, which the tracker must see whole to refuse).
    margin *= 4;
    region = growths == 0 ? grown(united(region, b), margin, params.block_size, frame) : whole;
  }
}

TrackResult Tracker::track(const ImageView& gray, EdgeSource& edges, double t, Method m,
                           const Params& params, const TrackerParams& tp, Trace* trace) {
  if (trace) trace->clear();
  TrackResult r;
  const ImageView& frame = edges.frame();
  if (!frame.valid()) {
    r.status = frame.empty() ? Status::EmptyImage : Status::InvalidImage;
    r.detail = "no usable frame";
    return r;
  }
  if (!inner_) {
    const ImageView all = edges.region({0, 0, frame.width, frame.height});
    std::optional<Features> f = acquire(gray, all, m, params, tp, r.detail);
    if (!f) {
      r.status = tp.acquisition == Acquisition::Manual ? Status::NoInnerPoint : Status::Searching;
      return r;
    }
    r.detail.clear();
    accept(*f, t, frame, tp, r);
    return r;
  }

  const Features f = estimate_around(edges, m, params, tp, trace);
  if (f.status == Status::InvalidParameters || f.status == Status::InvalidImage ||
      f.status == Status::EmptyImage) {
    r.status = f.status;  // not the object's doing: say what is wrong, keep the track
    r.features = f;
    return r;
  }
  std::string why = refused(f, frame, tp);
  if (why.empty()) {
    accept(f, t, frame, tp, r);
    return r;
  }
  // Refused: report the last good features and keep the inner point; the object may come back
  // under it (a brief occlusion). After `patience` frames, drop the track.
  ++refused_in_a_row_;
  r.status = Status::Lost;
  r.detail = why;
  // Only an accepted estimate is ever reported: with none yet, no features at all.
  r.features = last_good_ ? *last_good_ : Features{};
  r.has_pose = last_good_.has_value();
  r.pose = pose_;
  r.raw_pose = raw_pose_;
  push_.reset();
  if (refused_in_a_row_ > tp.patience) {
    r.detail += "; the track is dropped";
    reset();
  }
  return r;
}

}  // namespace projtrack
