#include "core/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace projtrack {

namespace {

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g %%", 100 * fraction);
  return buf;
}

}  // namespace

double max_area_share(const TrackerParams& tp, Origin origin) {
  return origin == Origin::User ? std::max(tp.max_area, kUserMaxArea) : tp.max_area;
}

std::string why_implausible(const Features& f, int width, int height, const TrackerParams& tp,
                            Origin origin) {
  if (!f.valid()) return f.detail.empty() ? std::string(status_name(f.status)) : f.detail;
  const double frame = static_cast<double>(width) * height;
  if (f.status == EstimateStatus::CoversFrame)
    return "the estimate covers the frame (a leak, or no closed contour around the inner point)";
  if (f.area > max_area_share(tp, origin) * frame)
    return "the estimate covers " + percent(f.area / frame) + " of the frame (a leak)";
  if (f.area < (origin == Origin::User ? kLeastArea : tp.min_area * frame))
    return "the estimate is too small (" + percent(f.area / frame) + " of the frame)";
  return {};
}

std::string why_refused(const Features& f, int width, int height, const TrackerParams& tp,
                        const Features* last, double limit, Origin origin) {
  std::string why = why_implausible(f, width, height, tp, origin);
  if (!why.empty() || !last) return why;
  const double ratio = f.area / last->area;
  char buf[96];
  if (ratio > tp.leak_factor) {
    if (f.area > limit)
      std::snprintf(buf, sizeof buf, "the area passed %.1f× the last frame's: a leak, not filled",
                    tp.leak_factor);
    else
      std::snprintf(buf, sizeof buf, "the area jumped %.1f× since the last frame (a leak)", ratio);
    return buf;
  }
  if (ratio < 1 / tp.leak_factor) {
    std::snprintf(buf, sizeof buf, "the area shrank to %.2f× of the last frame's", ratio);
    return buf;
  }
  return {};
}

double area_limit(int width, int height, const TrackerParams& tp, const Features* last,
                  Origin origin) {
  double limit = std::max(max_area_share(tp, origin), 0.0) * width * height;
  if (last && tp.leak_factor > 0) limit = std::min(limit, tp.leak_factor * last->area);
  return std::isfinite(limit) ? std::min(std::floor(limit) + 1, kMaxAreaLimit) : kMaxAreaLimit;
}

}  // namespace projtrack
