// The time between samples of a video signal, whose timestamps may be missing or jump back.
#pragma once

#include <cmath>

namespace projtrack {

// Frames a second assumed where a stream says nothing of time: the common camera rate.
inline constexpr double kAssumedFrameRate = 30.0;

// The clock of a filter fed one sample per frame. step(t) returns the seconds since the previous
// sample: when time stands still, goes back (a seek) or is not finite, one assumed frame, and the
// clock then follows `t` again (or moves on by that frame when `t` is not finite).
class SampleClock {
 public:
  void start(double t) { now_ = t; }
  double step(double t) {
    double dt = t - now_;
    if (!(dt > 0) || !std::isfinite(dt)) dt = 1.0 / kAssumedFrameRate;
    now_ = std::isfinite(t) ? t : now_ + dt;
    return dt;
  }
  double now() const { return now_; }  // the time of the last sample

 private:
  double now_ = 0;
};

}  // namespace projtrack
