// A "push": the tracked object moved quickly toward the camera and back — a click in 3D.
#pragma once

#include "sample_clock.hpp"

namespace projtrack {

// Watches the relative depth (1 at acquisition, growing as the object nears the camera). A push
// is a rise of more than `threshold` above the resting depth that falls back below half of that
// rise within `max_duration` seconds. Slower changes move the resting depth instead, so walking
// closer is not a click.
class PushDetector {
 public:
  struct Params {
    double threshold = 0.12;    // relative rise of depth, e.g. 0.12 = 12 %
    double max_duration = 0.8;  // s, from leaving rest to returning
    double rest_time = 1.0;     // s, time constant of the resting depth
  };

  void set_params(const Params& p) { p_ = p; }

  // Feeds one depth sample at `t` seconds; true exactly once per push, when it returns.
  bool update(double depth, double t);
  void reset() { state_ = State::Unset; }

 private:
  enum class State { Unset, Resting, Pushed };
  Params p_;
  State state_ = State::Unset;
  double rest_ = 1.0, t_start_ = 0;
  SampleClock clock_;
};

}  // namespace projtrack
