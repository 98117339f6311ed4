#include "tracker/refusal_policy.hpp"

#include <algorithm>
#include <bitset>

namespace projtrack {

AfterRefusal after_refusal(const Track& t, const TrackerParams& tp, bool forced,
                           bool drops_unsteady) {
  AfterRefusal out;
  // An object found without the user's point whose estimates are refused on and off is a
  // fragment the estimates cannot hold (TrackerParams::unsteady).
  const int window = std::min(2 * tp.unsteady, 31);
  const bool unsteady =
      !forced && drops_unsteady && !t.seeded && tp.unsteady > 0 && t.refused_in_a_row == 1 &&
      static_cast<int>(std::bitset<32>(t.refusals & ((1u << window) - 1)).count()) >= tp.unsteady;
  if (unsteady) out.note = "; refused on and off: an unsteady fragment, not an object";
  out.drop = forced || unsteady || t.refused_in_a_row > tp.patience;
  if (out.drop) out.note += "; the track is dropped";
  return out;
}

}  // namespace projtrack
