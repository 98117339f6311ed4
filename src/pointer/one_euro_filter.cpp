#include "pointer/one_euro_filter.hpp"

#include <cmath>

namespace projtrack {

namespace {
double alpha(double cutoff, double dt) {
  const double tau = 1.0 / (2.0 * M_PI * cutoff);
  return 1.0 / (1.0 + tau / dt);
}
}  // namespace

double OneEuroFilter::filter(double x, double t) {
  if (!initialised_ || !std::isfinite(x_prev_)) {
    initialised_ = true;
    x_prev_ = x;
    dx_prev_ = 0;
    clock_.start(t);
    return x;
  }
  const double dt = clock_.step(t);
  const double dx = (x - x_prev_) / dt;
  const double dx_hat = dx_prev_ + alpha(p_.d_cutoff, dt) * (dx - dx_prev_);
  const double cutoff = p_.min_cutoff + p_.beta * std::abs(dx_hat);
  const double x_hat = x_prev_ + alpha(cutoff, dt) * (x - x_prev_);
  x_prev_ = x_hat;
  dx_prev_ = dx_hat;
  return x_hat;
}

}  // namespace projtrack
