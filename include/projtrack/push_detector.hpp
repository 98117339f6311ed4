// A "push": the tracked object moved quickly toward the camera and back — a click in 3D.
#pragma once

#include <cmath>

#include "sample_clock.hpp"

namespace projtrack {

// Watches the relative depth (1 at acquisition, growing as the object nears the camera). A push
// is a rise of more than `threshold` above the resting depth that falls back below half of that
// rise within `max_duration` seconds. Slower changes move the resting depth instead, so walking
// closer is not a click. Given the object's width and height (its box), a push must also have
// grown both by more than half the threshold: nearing the camera scales the whole projection,
// where a walker's legs opening widen it only.
class PushDetector {
 public:
  struct Params {
    double threshold = 0.12;    // relative rise of depth, e.g. 0.12 = 12 %
    double max_duration = 0.8;  // s, from leaving rest to returning
    double rest_time = 1.0;     // s, time constant of the resting depth
    // The rise must also pass this many times the depth's own jitter at rest (its mean relative
    // deviation from the resting depth): a track whose area is noisy needs a clearer push.
    double jitter_factor = 3.0;
    // No push starts in the first `settle` seconds of a track: its resting depth and jitter are
    // not known yet (a fragment found a moment ago jumps in area).
    double settle = 0.5;
  };

  void set_params(const Params& p) { p_ = p; }

  // Feeds one depth sample at `t` seconds; true exactly once per push, when it returns.
  bool update(double depth, double t) { return update(depth, NAN, NAN, t); }
  // The same with the object's width and height (any unit; NaN: not known, not checked).
  bool update(double depth, double width, double height, double t);
  void reset() { state_ = State::Unset; }

 private:
  enum class State { Unset, Resting, Pushed };
  Params p_;
  State state_ = State::Unset;
  double rest_ = 1.0, t_start_ = 0, jitter_ = 0, t_first_ = 0;
  double rest_w_ = NAN, rest_h_ = NAN, peak_w_ = NAN, peak_h_ = NAN;  // the box's sides
  SampleClock clock_;
};

}  // namespace projtrack
