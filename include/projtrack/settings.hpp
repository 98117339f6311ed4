// The settings bundle: everything a user sets on a tracker (the method, the estimators'
// parameters, edge detection, the tracker's own parameters), with every default written once, in
// the structs it holds. The element's property table and the Python module each hold one and map
// their names onto it (docs/architecture.md, "One name per concept"); neither holds a default.
#pragma once

#include <string>

#include "edge_detection.hpp"
#include "method.hpp"
#include "params.hpp"
#include "tracker_params.hpp"

namespace projtrack {

struct Settings {
  Method method = Method::GapTolerantFilling;  // the paper's filling, tolerant of gaps: ours
  Params params;
  EdgeParams edges;
  TrackerParams tracker;
};

// Empty when the tracker can work with `tp`; otherwise says which parameter is out of range.
std::string validate(const TrackerParams& tp);
// The one check of a user's settings: empty when every value is in range and they work together;
// otherwise says which one is not, and why. Stricter than what Tracker::track refuses per frame:
// it also refuses what EdgeMap would clamp (negative thresholds, blur passes out of range), which
// a user means as no value of ours.
std::string validate(const Settings& s);

}  // namespace projtrack
