// The edges model's automatic acquisition, as the original system did it: where the frame
// moves, the estimator from candidate seeds; the most compact moving region wins.
#pragma once

#include <optional>
#include <string>

#include "estimator.hpp"
#include "motion_detector.hpp"
#include "tracker_params.hpp"

namespace projtrack {

class MotionAcquisition {
 public:
  // The first estimate of a new track on this frame (`gray` and its `edges`), by
  // TrackerParams::acquisition; none (and `why`) while there is nothing to take. `limit` is the
  // area the fills may stop at.
  std::optional<Features> acquire(const ImageView& gray, const ImageView& edges, Estimator& est,
                                  const Params& params, double limit, const TrackerParams& tp,
                                  std::string& why);
  // Motion history is stale after a track: the next search compares fresh frames.
  void reset() { motion_.reset(); }

 private:
  MotionDetector motion_;
  MotionDetector::Motion moved_;
  Acquisition last_mode_ = Acquisition::Auto;
};

}  // namespace projtrack
