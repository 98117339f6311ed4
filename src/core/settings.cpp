#include "projtrack/settings.hpp"

#include <cmath>
#include <cstdio>

namespace projtrack {

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
  if (std::string why = validate(s.params); !why.empty()) return why;
  if (std::string why = validate(s.edges); !why.empty()) return why;
  // EdgeMap clamps these; a user who gives them means something we do not do.
  if (!(s.edges.low >= 0) || !(s.edges.high >= 0))
    return "edge_threshold_low and edge_threshold_high must be at least 0";
  if (s.edges.blur < 0 || s.edges.blur > kMaxBlurPasses)
    return "blur = " + std::to_string(s.edges.blur) + " is outside [0, " +
           std::to_string(kMaxBlurPasses) + "]";
  // What the element's property ranges keep in range, and Python's keywords do not.
  const TrackerParams& tp = s.tracker;
  if (!(tp.leak_factor > 1 && std::isfinite(tp.leak_factor)))
    return "leak_factor = " + std::to_string(tp.leak_factor) + " must be a number above 1";
  if (!(tp.filter.min_cutoff > 0 && std::isfinite(tp.filter.min_cutoff)))
    return "smoothing_min_cutoff must be a positive number (Hz)";
  if (!(tp.filter.beta >= 0 && std::isfinite(tp.filter.beta)))
    return "smoothing_beta must be a number of at least 0";
  if (!(tp.push.threshold > 0 && std::isfinite(tp.push.threshold)))
    return "push_threshold must be a positive number";
  return validate(tp);
}

}  // namespace projtrack
