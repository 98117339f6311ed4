// Whether an estimate can be the tracked object: the rules that refuse leaks and collapses.
#pragma once

#include <string>

#include "projtrack/features.hpp"
#include "projtrack/params.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

// Empty when `f` can be a new track's first estimate in a width × height frame; else why not.
std::string why_implausible(const Features& f, int width, int height, const TrackerParams& tp);

// Empty when `f` continues a track whose last accepted estimate is `last` (null: none yet);
// else why it is refused. `limit` is the area the fills stopped at (see area_limit).
std::string why_refused(const Features& f, int width, int height, const TrackerParams& tp,
                        const Features* last, double limit);

// The area above which an estimate would be refused anyway, px²: the fills can stop there
// (EstimateOptions::area_limit), so a leak costs about the object's size rather than the frame's.
double area_limit(int width, int height, const TrackerParams& tp, const Features* last);

}  // namespace projtrack
