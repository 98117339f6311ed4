#include "tracker/tracker_state.hpp"

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

void TrackerState::reset() {
  drop(Keep::Nothing);
  edges_acquisition.reset();
}

void TrackerState::drop(Keep keep) {
  Track& t = track_;
  if (t.last) {
    t.lost_area = t.last->area;
    t.lost_centroid = t.last->centroid;
  }
  t.inner.reset();
  t.seed_box.reset();
  t.last.reset();
  t.velocity = {0, 0};
  t.refused_in_a_row = 0;
  t.refusals = 0;
  t.searched = 0;
  pointer.end();
  motion.reset();
  moved = {};
  moved_before = {};
  if (keep == Keep::Colours) {
    object.forget_position();
  } else {
    object.forget();
  }
}

void TrackerState::use_model(ObjectModelKind kind) {
  if (kind == model_) return;
  const std::optional<Point2i> inner = track_.inner;
  reset();
  track_.inner = inner;
  model_ = kind;
}

bool TrackerState::accept(const Features& f, bool resumed, double t, int width, int height,
                          const TrackerParams& tp) {
  Track& k = track_;
  const bool starts = !k.last;
  if (starts) {
    k.seeded = k.inner.has_value() && !resumed;
    k.still = 0;
    pointer.restart();  // depth needs no reference: one rule however the track (re)starts
  }
  k.velocity = k.last
                   ? Point2d{f.centroid.x - k.last->centroid.x, f.centroid.y - k.last->centroid.y}
                   : Point2d{0, 0};
  k.inner = f.inner_point;
  k.seed_box.reset();
  k.last = f;
  k.refused_in_a_row = 0;
  k.refusals <<= 1;
  k.searched = 0;
  pointer.update(f, width, height, t, tp);
  return starts;
}

void TrackerState::refuse() {
  ++track_.refused_in_a_row;
  track_.refusals = (track_.refusals << 1) | 1u;
  pointer.refuse();
}

void TrackerState::forget_colours() { object.forget(); }

}  // namespace projtrack
