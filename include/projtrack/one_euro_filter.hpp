// The One Euro filter (Casiez, Roussel & Vogel, CHI 2012): the standard smoother for pointers.
#pragma once

#include "sample_clock.hpp"

namespace projtrack {

// A low-pass filter whose cutoff rises with speed: slow motion is smoothed hard (no jitter), fast
// motion little (no lag). min_cutoff (Hz) sets the smoothing at rest, beta how fast the cutoff
// rises with speed (in units of the signal per second).
class OneEuroFilter {
 public:
  struct Params {
    double min_cutoff = 1.0;  // Hz
    double beta = 0.5;        // per (signal unit / s)
    double d_cutoff = 1.0;    // Hz, for the speed estimate
  };

  void set_params(const Params& p) { p_ = p; }

  // Filters sample `x` taken at `t` seconds. A time that does not advance (unknown timestamps)
  // is taken as one frame after the previous sample (see SampleClock).
  double filter(double x, double t);
  void reset() { initialised_ = false; }

 private:
  Params p_;
  bool initialised_ = false;
  double x_prev_ = 0, dx_prev_ = 0;
  SampleClock clock_;
};

}  // namespace projtrack
