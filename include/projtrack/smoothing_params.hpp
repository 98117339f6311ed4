// The pose's smoothing: the One Euro filter's parameters (Casiez, Roussel & Vogel, CHI 2012).
#pragma once

namespace projtrack {

// min_cutoff (Hz) sets the smoothing at rest, beta how fast the cutoff rises with speed (in units
// of the signal per second).
struct SmoothingParams {
  double min_cutoff = 1.0;  // Hz
  double beta = 0.5;        // per (signal unit / s)
  double d_cutoff = 1.0;    // Hz, for the speed estimate
};

}  // namespace projtrack
