// The edges model's automatic acquisition, as the original system did it: where the frame
// moves, the estimator from candidate seeds; the most compact moving region wins.
#pragma once

#include <optional>
#include <string>

#include "acquisition/motion_detector.hpp"
#include "core/scratch_mask.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/tracker_params.hpp"
#include "projtrack/work_budget.hpp"

namespace projtrack {

class MotionAcquisition {
 public:
  // The first estimate of a new track on this frame (`gray` and its `edges`) where it moved
  // (Acquisition::Auto, by TrackerParams::strategy); none (and `why`) while there is nothing to
  // take. `limit` is the area the fills may stop at. Every seed's estimate spends from `budget`:
  // once it runs out (or its stop flag is set) no further seed is tried, and the best of the
  // seeds tried in full is taken (budget.ran_out() says whether the search was cut short).
  std::optional<Features> acquire(const ImageView& gray, const ImageView& edges, Estimator& est,
                                  const Params& params, double limit, const TrackerParams& tp,
                                  WorkBudget& budget, std::string& why);
  // Called on every frame searched, with the acquisition mode in force: motion history from
  // before a switch of mode is stale.
  void use_mode(Acquisition mode) {
    if (mode != last_mode_) motion_.reset();
    last_mode_ = mode;
  }
  // Motion history is stale after a track: the next search compares fresh frames.
  void reset() { motion_.reset(); }

 private:
  MotionDetector motion_;
  // This frame's pixels of fills cut short by the area limit (regions too large to be the object):
  // a seed in one is not tried. All zero out of `too_large_box_` between frames.
  ScratchMask too_large_;
  Rect too_large_box_;
  MotionDetector::Motion moved_;
  Acquisition last_mode_ = Acquisition::Auto;
};

}  // namespace projtrack
