#include "projtrack/flow_model_params.hpp"

#include <cmath>
#include <cstdio>

namespace projtrack {

namespace {

// "name = value is outside [low, high]" when `v` is not a number in it (`open_low`: low itself
// is outside too).
std::string outside(const char* name, double v, double low, double high, bool open_low = false) {
  const bool in = std::isfinite(v) && (open_low ? v > low : v >= low) && v <= high;
  if (in) return {};
  char why[160];
  std::snprintf(why, sizeof why, "flow.%s = %.6g is outside %s%.6g, %.6g]", name, v,
                open_low ? "(" : "[", low, high);
  return why;
}

}  // namespace

std::string validate(const FlowModelParams& p) {
  const std::string checks[] = {
      outside("work_pixels", p.work_pixels, 1000, 1e9),
      outside("object_pixels", p.object_pixels, 100, 1e8),
      outside("flow_span", p.flow_span, 0, 1e6),
      outside("box_pixels", p.box_pixels, 100, 1e7),
      outside("prior_spread", p.prior_spread, 0, 10),
      outside("prior_floor", p.prior_floor, 0, 0.499, true),
      outside("learning_rate", p.learning_rate, 0, 1),
      outside("first_share", p.first_share, 0, 1),
      outside("local_colour_weight", p.local_colour_weight, 0, 1),
      outside("local_colour_cells", p.local_colour_cells, 1, 16),
      outside("colour_ring", p.colour_ring, 0, 10, true),
      outside("motion_ring", p.motion_ring, 0, 10, true),
      outside("motion_weight", p.motion_weight, 0, 50),
      outside("min_separation", p.min_separation, 0, 1e6),
      outside("memory_weight", p.memory_weight, 0, 1),
      outside("memory_refresh", p.memory_refresh, 0, 1),
      outside("memory_fade", p.memory_fade, 0, 0.999),
      outside("keep_share", p.keep_share, 0, 1),
      outside("new_motion_share", p.new_motion_share, 0, 1),
      outside("new_core", p.new_core, 0, 1),
  };
  for (const std::string& why : checks)
    if (!why.empty()) return why;
  return {};
}

}  // namespace projtrack
