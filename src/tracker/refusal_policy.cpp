#include "tracker/refusal_policy.hpp"

namespace projtrack {

AfterRefusal after_refusal(const Track& t, const TrackerParams& tp, bool forced) {
  AfterRefusal out;
  out.drop = forced || t.refused_in_a_row > tp.patience;
  if (out.drop) out.note = "; the track is dropped";
  return out;
}

}  // namespace projtrack
