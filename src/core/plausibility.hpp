// Whether an estimate can be the tracked object: the rules that refuse leaks and collapses.
#pragma once

#include <string>

#include "projtrack/features.hpp"
#include "projtrack/params.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

// Whose object it is: one the tracker found by itself, or the one the user pointed at. The user's
// may be as large as the picture allows (TrackerParams::max_area is the largest object the
// tracker takes by itself): only an estimate that leaves no surroundings to tell it from, more
// than kUserMaxArea of the frame, is a leak; and as small as can be measured at all (kLeastArea
// px²: a 3×3 patch), where TrackerParams::min_area is the least the tracker takes by itself.
enum class Origin { Found, User };
inline constexpr double kUserMaxArea = 0.9;
inline constexpr double kLeastArea = 9;
double max_area_share(const TrackerParams& tp, Origin origin);

// Empty when `f` can be a new track's first estimate in a width × height frame; else why not.
std::string why_implausible(const Features& f, int width, int height, const TrackerParams& tp,
                            Origin origin = Origin::Found);

// Empty when `f` continues a track whose last accepted estimate is `last` (null: none yet);
// else why it is refused. `limit` is the area the fills stopped at (see area_limit).
std::string why_refused(const Features& f, int width, int height, const TrackerParams& tp,
                        const Features* last, double limit, Origin origin = Origin::Found);

// The area above which an estimate would be refused anyway, px²: the fills can stop there
// (EstimateOptions::area_limit), so a leak costs about the object's size rather than the frame's.
double area_limit(int width, int height, const TrackerParams& tp, const Features* last,
                  Origin origin = Origin::Found);

}  // namespace projtrack
