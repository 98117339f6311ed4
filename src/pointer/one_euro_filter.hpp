// The One Euro filter (Casiez, Roussel & Vogel, CHI 2012): the standard smoother for pointers.
#pragma once

#include "projtrack/sample_clock.hpp"
#include "projtrack/smoothing_params.hpp"

namespace projtrack {

// A low-pass filter whose cutoff rises with speed: slow motion is smoothed hard (no jitter), fast
// motion little (no lag); its parameters are SmoothingParams (smoothing_params.hpp).
class OneEuroFilter {
 public:
  using Params = SmoothingParams;

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
