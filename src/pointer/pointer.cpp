#include "pointer/pointer.hpp"

#include <cmath>

namespace projtrack {

void Pointer::start(double area) {
  area0_ = area > 0 ? area : 1.0;
  resume();
}

void Pointer::resume() {
  fx_.reset();
  fy_.reset();
  fdepth_.reset();
  push_.reset();
}

void Pointer::update(const Features& f, int width, int height, double t, const TrackerParams& tp) {
  raw_ = {2 * (f.centroid.x + 0.5) / width - 1, 2 * (f.centroid.y + 0.5) / height - 1,
          area0_ > 0 ? std::sqrt(f.area / area0_) : 1.0};
  if (tp.smoothing) {
    fx_.set_params(tp.filter);
    fy_.set_params(tp.filter);
    fdepth_.set_params(tp.filter);
    pose_ = {fx_.filter(raw_.x, t), fy_.filter(raw_.y, t), fdepth_.filter(raw_.depth, t)};
  } else {
    pose_ = raw_;
  }
  push_.set_params(tp.push);
  pushed_ = push_.update(raw_.depth, f.bbox.width, f.bbox.height, t);
}

}  // namespace projtrack
