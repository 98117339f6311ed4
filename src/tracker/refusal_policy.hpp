// When a track waits, and when refusals end it: the policy every object model shares.
#pragma once

#include <string>

#include "core/track.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

// What a track waits for when acquisition is manual and no point was given.
inline constexpr const char* kNoInnerPoint = "no inner point: set one, or click in the video";
inline bool waits_for_user(const Track& t, const TrackerParams& tp) {
  return !t.inner && tp.acquisition == Acquisition::Manual;
}

// After a refused frame (TrackerState::refuse): whether the track ends, and why beyond the
// refusal. `forced`: the caller ends it whatever the count (a model's veto). `drops_unsteady`:
// the model drops a track found without the user's point that is refused on and off
// (ObjectModel::drops_unsteady, TrackerParams::unsteady).
struct AfterRefusal {
  bool drop = false;
  std::string note;  // appended to the refusal's reason
};
AfterRefusal after_refusal(const Track& t, const TrackerParams& tp, bool forced,
                           bool drops_unsteady);

}  // namespace projtrack
