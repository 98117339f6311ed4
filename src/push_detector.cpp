#include "push_detector.hpp"

#include <cmath>

namespace projtrack {

bool PushDetector::update(double depth, double t) {
  if (!std::isfinite(depth)) return false;
  if (state_ == State::Unset) {
    state_ = State::Resting;
    rest_ = depth;
    t_prev_ = t;
    return false;
  }
  double dt = t - t_prev_;
  // Time that stands still or goes back (a seek): one frame, and the clock follows `t` again.
  if (!(dt > 0) || !std::isfinite(dt)) dt = 1.0 / 30.0;
  if (std::isfinite(t) && t < t_prev_) t_start_ -= t_prev_ - t;  // keep the push's duration
  t_prev_ = std::isfinite(t) ? t : t_prev_ + dt;
  const double now = t_prev_;
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
