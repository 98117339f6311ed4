#include "projtrack/push_detector.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

// Rest follows `v` (a NaN rest takes it at once); NaN samples leave it.
void follow(double& rest, double v, double k) {
  if (!std::isfinite(v)) return;
  rest = std::isfinite(rest) ? rest + k * (v - rest) : v;
}

// Grew by more than `share` over rest; true when either is not known.
bool grew(double peak, double rest, double share) {
  return !std::isfinite(peak) || !std::isfinite(rest) || peak > rest * (1 + share);
}

}  // namespace

bool PushDetector::update(double depth, double width, double height, double t) {
  if (!std::isfinite(depth)) return false;
  if (state_ == State::Unset) {
    state_ = State::Resting;
    rest_ = depth;
    jitter_ = 0;
    rest_w_ = std::isfinite(width) ? width : NAN;
    rest_h_ = std::isfinite(height) ? height : NAN;
    clock_.start(t);
    t_first_ = clock_.now();
    return false;
  }
  const double before = clock_.now();
  const double dt = clock_.step(t);
  if (std::isfinite(t) && t < before) {  // keep the push's duration and the time settled
    t_start_ -= before - t;
    t_first_ -= before - t;
  }
  const double now = clock_.now();
  if (state_ == State::Resting) {
    if (!(now - t_first_ < p_.settle) &&
        depth > rest_ * (1 + p_.threshold + p_.jitter_factor * jitter_)) {
      state_ = State::Pushed;
      t_start_ = now;
      peak_w_ = width;
      peak_h_ = height;
    } else {
      const double k = 1 - std::exp(-dt / p_.rest_time);
      if (rest_ > 0) jitter_ += k * (std::abs(depth / rest_ - 1) - jitter_);
      rest_ += k * (depth - rest_);
      follow(rest_w_, width, k);
      follow(rest_h_, height, k);
    }
    return false;
  }
  // Pushed: back near rest in time is a push (if the whole projection grew); staying out too
  // long is a move.
  if (std::isfinite(width)) peak_w_ = std::isfinite(peak_w_) ? std::max(peak_w_, width) : width;
  if (std::isfinite(height)) peak_h_ = std::isfinite(peak_h_) ? std::max(peak_h_, height) : height;
  if (depth < rest_ * (1 + p_.threshold / 2)) {
    state_ = State::Resting;
    return now - t_start_ <= p_.max_duration && grew(peak_w_, rest_w_, p_.threshold / 2) &&
           grew(peak_h_, rest_h_, p_.threshold / 2);
  }
  if (now - t_start_ > p_.max_duration) {
    state_ = State::Resting;
    rest_ = depth;
    rest_w_ = width;
    rest_h_ = height;
  }
  return false;
}

}  // namespace projtrack
