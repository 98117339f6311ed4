#include "projtrack/settings.hpp"

#include <cmath>
#include <cstdio>

namespace projtrack {

namespace {

// "name = value is outside [low, high]" when `v` is not a number in `range`.
std::string outside(const char* name, double v, SettingRange range) {
  if (range.contains(v)) return {};
  char why[160];
  std::snprintf(why, sizeof why, "%s = %.15g is outside [%.15g, %.15g]", name, v, range.low,
                range.high);
  return why;
}

}  // namespace

std::string validate(const TrackerParams& tp) {
  if (!(tp.max_work >= 0 && tp.max_work <= kMaxMaxWork)) {
    char why[120];
    std::snprintf(why, sizeof why, "max_work = %.15g is outside [0, %.15g]", tp.max_work,
                  kMaxMaxWork);
    return why;
  }
  return validate(tp.flow);
}

std::string validate(const Settings& s) {
  if (!is_method(s.method))
    return "method " + std::to_string(static_cast<int>(s.method)) + " is no method";
  if (s.edges.blur < 0 || s.edges.blur > kMaxBlurPasses)
    return "blur = " + std::to_string(s.edges.blur) + " is outside [0, " +
           std::to_string(kMaxBlurPasses) + "]";
  // The ranges the element's property specs keep values in, checked here for Python's keywords
  // and the library's callers.
  const TrackerParams& tp = s.tracker;
  const std::string checks[] = {
      outside("edge_threshold_low", s.edges.low, kEdgeThresholdRange),
      outside("edge_threshold_high", s.edges.high, kEdgeThresholdRange),
      outside("leak_factor", tp.leak_factor, kLeakFactorRange),
      outside("smoothing_min_cutoff", tp.filter.min_cutoff, kSmoothingMinCutoffRange),
      outside("smoothing_beta", tp.filter.beta, kSmoothingBetaRange),
      outside("push_threshold", tp.push.threshold, kPushThresholdRange),
  };
  for (const std::string& why : checks)
    if (!why.empty()) return why;
  if (std::string why = validate(s.params); !why.empty()) return why;
  if (std::string why = validate(s.edges); !why.empty()) return why;
  return validate(tp);
}

}  // namespace projtrack
