#include "tracker/tracker_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace projtrack {

void TrackerState::seed(Point2i p) {
  reset();
  track_.inner = p;
}

void TrackerState::seed_box(const Rect& box) {
  reset();
  // The centre in 64 bits: a box's corner and size may each be near INT_MAX.
  track_.inner = Point2i{static_cast<int>(box.x + static_cast<std::int64_t>(box.width) / 2),
                         static_cast<int>(box.y + static_cast<std::int64_t>(box.height) / 2)};
  track_.seed_box = box;
}

void TrackerState::seed_mask(const cv::Mat& mask, const Rect& box, Point2i deepest) {
  seed_box(box);
  track_.inner = deepest;
  track_.seed_mask = mask;
}

void TrackerState::drop() {
  Track& t = track_;
  if (t.last) {
    t.lost_area = t.last->area;
    t.lost_centroid = t.last->centroid;
  }
  t.inner.reset();
  t.seed_box.reset();
  t.seed_mask.release();
  t.last.reset();
  t.velocity = {0, 0};
  t.accepted = 0;
  t.refused_in_a_row = 0;
  t.refusals = 0;
  pointer.end();
}

void TrackerState::switch_model() {
  // The user's start (point, box, mask) is kept: the new model starts from it its own way.
  const std::optional<Point2i> inner = track_.inner;
  const std::optional<Rect> box = track_.seed_box;
  const cv::Mat mask = track_.seed_mask;
  reset();
  track_.inner = inner;
  track_.seed_box = box;
  track_.seed_mask = mask;
}

bool TrackerState::accept(const Features& f, bool resumed, double t, int width, int height,
                          const TrackerParams& tp) {
  Track& k = track_;
  const bool starts = !k.last;
  k.accepted = starts ? 1 : k.accepted + 1;
  if (starts) {
    k.seeded = k.inner.has_value() && !resumed;
    pointer.restart();  // depth needs no reference: one rule however the track (re)starts
  }
  k.velocity = k.last && !k.across_change
                   ? Point2d{f.centroid.x - k.last->centroid.x, f.centroid.y - k.last->centroid.y}
                   : Point2d{0, 0};
  k.across_change = false;
  k.inner = f.inner_point;
  k.seed_box.reset();
  k.seed_mask.release();
  k.last = f;
  k.refused_in_a_row = 0;
  k.refusals <<= 1;
  pointer.update(f, width, height, t, tp);
  return starts;
}

void TrackerState::refuse() {
  ++track_.refused_in_a_row;
  track_.refusals = (track_.refusals << 1) | 1u;
  pointer.refuse();
}

namespace {

int to_int(double v) {
  return static_cast<int>(std::clamp(v, static_cast<double>(std::numeric_limits<int>::min()),
                                     static_cast<double>(std::numeric_limits<int>::max())));
}
// A pixel (its centre at +0.5) and a rectangle of pixels at sx × sy their size.
Point2i scaled(Point2i p, double sx, double sy) {
  return {to_int(std::floor((p.x + 0.5) * sx)), to_int(std::floor((p.y + 0.5) * sy))};
}
Rect scaled(const Rect& r, double sx, double sy) {
  const double x0 = std::floor(r.x * sx), y0 = std::floor(r.y * sy);
  const double x1 = std::ceil((static_cast<double>(r.x) + r.width) * sx);
  const double y1 = std::ceil((static_cast<double>(r.y) + r.height) * sy);
  return {to_int(x0), to_int(y0), to_int(x1 - x0), to_int(y1 - y0)};
}
Point2d scaled(Point2d c, double sx, double sy) {  // pixel centres at integer coordinates
  return {(c.x + 0.5) * sx - 0.5, (c.y + 0.5) * sy - 0.5};
}

}  // namespace

void TrackerState::rescale(double sx, double sy, int width, int height) {
  if (!(sx > 0 && sy > 0 && std::isfinite(sx) && std::isfinite(sy))) return;
  Track& t = track_;
  if (t.inner) t.inner = scaled(*t.inner, sx, sy);
  // A box scaled rounds outward, and can pass the frame's edge by a pixel: clipped.
  if (t.seed_box) t.seed_box = clip_to_frame(scaled(*t.seed_box, sx, sy), width, height);
  if (t.last) {
    Features& f = *t.last;
    f.centroid = scaled(f.centroid, sx, sy);
    f.area *= sx * sy;
    f.bbox = clip_to_frame(scaled(f.bbox, sx, sy), width, height);
    f.reach = clip_to_frame(scaled(f.reach, sx, sy), width, height);
    f.seed = scaled(f.seed, sx, sy);
    f.inner_point = scaled(f.inner_point, sx, sy);
  }
  t.velocity = {t.velocity.x * sx, t.velocity.y * sy};
  t.across_change = true;
  t.lost_area *= sx * sy;
  t.lost_centroid = scaled(t.lost_centroid, sx, sy);
  // Depth, √(area ÷ the frame's area), needs no rescaling.
}

void TrackerState::restart_within_last_box() {
  // The start within a box takes the object's first silhouette there, as from a user's box; the
  // last estimate, kept, makes it no new track (accept()).
  if (track_.last && !track_.seed_box) track_.seed_box = track_.last->bbox;
  track_.across_change = true;
}

}  // namespace projtrack
