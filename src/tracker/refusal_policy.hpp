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

// After a refused frame (TrackerState::refuse): whether the track ends — after
// TrackerParams::patience refused frames in a row, or at once when `forced` (a model's veto) —
// and what to add to the refusal's reason.
struct AfterRefusal {
  bool drop = false;
  std::string note;  // appended to the refusal's reason
};
AfterRefusal after_refusal(const Track& t, const TrackerParams& tp, bool forced);

}  // namespace projtrack
