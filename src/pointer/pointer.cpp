#include "pointer/pointer.hpp"

#include <cmath>

namespace projtrack {

double depth_of(double area, int width, int height) {
  const double frame = static_cast<double>(width) * height;
  return frame > 0 && area > 0 ? std::sqrt(area / frame) : 0.0;
}

void Pointer::restart() {
  fx_.reset();
  fy_.reset();
  fdepth_.reset();
  note(gestures_.restart());
}

void Pointer::end() { note(gestures_.restart()); }

void Pointer::update(const Features& f, int width, int height, double t, const TrackerParams& tp) {
  raw_ = {2 * (f.centroid.x + 0.5) / width - 1, 2 * (f.centroid.y + 0.5) / height - 1,
          depth_of(f.area, width, height)};
  if (tp.smoothing && raw_.depth > 0) {
    fx_.set_params(tp.filter);
    fy_.set_params(tp.filter);
    fdepth_.set_params(tp.filter);
    // Depth is smoothed as its logarithm: its relative changes are what the filter's speed
    // term sees, whatever the object's size (a small object's depth is small).
    pose_ = {fx_.filter(raw_.x, t), fy_.filter(raw_.y, t),
             std::exp(fdepth_.filter(std::log(raw_.depth), t))};
  } else {
    pose_ = raw_;
  }
  gestures_.set_params(tp.push);
  note(gestures_.update(raw_.depth, f.bbox.width, f.bbox.height, t));
}

void Pointer::note(Gesture g) {
  // A release is never lost to a later event of the same frame: the button must come up.
  if (g != Gesture::None && gesture_ != Gesture::Release) gesture_ = g;
}

Gesture Pointer::take_gesture() {
  const Gesture g = gesture_;
  gesture_ = Gesture::None;
  return g;
}

}  // namespace projtrack
