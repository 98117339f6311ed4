#include "projtrack/params.hpp"

#include <cmath>
#include <cstdio>

namespace projtrack {

namespace {
// "rays = 0 is outside [3, 1024]": whole numbers as such (%.15g: up to 15 digits, as given).
std::string out_of_range(const char* name, double value, double lo, double hi) {
  char text[200];
  std::snprintf(text, sizeof text, "%s = %.15g is outside [%.15g, %.15g]", name, value, lo, hi);
  return text;
}
}  // namespace

Params paper_params() {
  Params p;
  p.rays = 32;
  p.recursion = 2;
  p.block_size = 8;
  p.grid_size = 8;
  p.max_iterations = 10;
  p.convergence = 2.0;
  return p;
}

std::string validate(const Params& p) {
  if (p.rays < kMinRays || p.rays > kMaxRays)
    return out_of_range("rays", p.rays, kMinRays, kMaxRays);
  if (p.recursion < kMinRecursion || p.recursion > kMaxRecursion)
    return out_of_range("recursion", p.recursion, kMinRecursion, kMaxRecursion);
  long long total = 1;
  for (int i = 0; i < p.recursion; ++i) total *= p.rays;
  if (total > kMaxRaysPerCast)
    return "rays^recursion = " + std::to_string(total) + " exceeds " +
           std::to_string(kMaxRaysPerCast) + " rays per cast";
  if (p.block_size < 1 || p.block_size > kMaxCellSize)
    return out_of_range("block_size", p.block_size, 1, kMaxCellSize);
  if (p.grid_size < 1 || p.grid_size > kMaxCellSize)
    return out_of_range("grid_size", p.grid_size, 1, kMaxCellSize);
  if (p.max_iterations < 1 || p.max_iterations > kMaxIterations)
    return out_of_range("max_iterations", p.max_iterations, 1, kMaxIterations);
  if (!std::isfinite(p.convergence) || p.convergence < 0 || p.convergence > kMaxConvergence)
    return out_of_range("convergence", p.convergence, 0, kMaxConvergence);
  if (p.seed_radius < 0 || p.seed_radius > kMaxSeedRadius)
    return out_of_range("seed_radius", p.seed_radius, 0, kMaxSeedRadius);
  if (p.max_gap < 1 || p.max_gap > kMaxGap) return out_of_range("max_gap", p.max_gap, 1, kMaxGap);
  return {};
}

std::string validate(const EstimateOptions& o) {
  if (!std::isfinite(o.area_limit) || o.area_limit < 0 || o.area_limit > kMaxAreaLimit)
    return out_of_range("area_limit", o.area_limit, 0, kMaxAreaLimit);
  return {};
}

}  // namespace projtrack
