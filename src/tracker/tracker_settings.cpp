// Tracker::track with the settings bundle: the bundle's pieces into the frame's own overloads.
#include "projtrack/settings.hpp"
#include "projtrack/tracker.hpp"

namespace projtrack {

TrackResult Tracker::track(const ColorView& frame, double t, const Settings& s, Trace* trace) {
  return track(frame, s.edges, t, s.method, s.params, s.tracker, trace);
}

TrackResult Tracker::track(const ImageView& gray, double t, const Settings& s, Trace* trace) {
  return track(gray, s.edges, t, s.method, s.params, s.tracker, trace);
}

}  // namespace projtrack
