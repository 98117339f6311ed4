#include "push_detector.hpp"

#include <cmath>

namespace projtrack {

bool PushDetector::update(double depth, double t) {
  if (!std::isfinite(depth)) return false;
  if (state_ == State::Unset) {
    state_ = State::Resting;
    rest_ = depth;
    clock_.start(t);
    return false;
  }
  const double before = clock_.now();
  const double dt = clock_.step(t);
  if (std::isfinite(t) && t < before) t_start_ -= before - t;  // keep the push's duration
  const double now = clock_.now();
  if (state_ == State::Resting) {
    if (depth > rest_ * (1 + p_.threshold)) {
      state_ = State::Pushed;
      t_start_ = now;
    } else {
      rest_ += (1 - std::exp(-dt / p_.rest_time)) * (depth - rest_);
    }
    return false;
  }
  // Pushed: back near rest in time is a push; staying out too long is a move.
  if (depth < rest_ * (1 + p_.threshold / 2)) {
    state_ = State::Resting;
    return now - t_start_ <= p_.max_duration;
  }
  if (now - t_start_ > p_.max_duration) {
    state_ = State::Resting;
    rest_ = depth;
  }
  return false;
}

}  // namespace projtrack
