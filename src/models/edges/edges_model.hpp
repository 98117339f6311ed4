// The edges model (ObjectModelKind::Edges): the paper's tracker. It knows nothing of the object
// but its inner point and last box: the estimator runs on the frame's edges from the inner point
// the last estimate left, and a new object is the one the original system took (the frame centre,
// or the most compact region where the frame moves: acquisition/motion_acquisition).
#pragma once

#include "acquisition/motion_acquisition.hpp"
#include "models/object_model.hpp"

namespace projtrack {

class EdgesObjectModel final : public ObjectModel {
 public:
  bool tracking() const override { return following_; }
  Observation start(FrameEvidence& ev, const StartRequest& request, const Track& track) override;
  Observation follow(FrameEvidence& ev, const Track& track) override;
  void settle(Verdict verdict) override;
  bool rescale(double sx, double sy, int width, int height) override;
  bool relearn() override { return true; }  // the edges read no colour
  void forget(Forget what) override;

 private:
  // The estimate from `inner` on the edges around the track's last box (the whole frame before
  // there is one).
  Observation estimate_from(FrameEvidence& ev, Point2i inner, const Track& track);

  MotionAcquisition acquisition_;
  bool following_ = false;  // an estimate of this object was accepted
};

}  // namespace projtrack
