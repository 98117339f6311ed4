// The 3D pointer: x and y from the centroid, depth from the area, smoothed, with push clicks.
#pragma once

#include "projtrack/features.hpp"
#include "projtrack/one_euro_filter.hpp"
#include "projtrack/pose.hpp"
#include "projtrack/push_detector.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

class Pointer {
 public:
  // A new object: its area now is depth 1.
  void start(double area);
  // The same object found again after a loss: depth goes on from the first area; the filters
  // and the push detector start afresh (the object may have moved while it was lost).
  void resume();
  bool started() const { return area0_ > 0; }
  // One accepted estimate at `t` seconds in a width × height frame.
  void update(const Features& f, int width, int height, double t, const TrackerParams& tp);
  // A refused frame: a push in progress does not survive it.
  void cancel_gesture() { push_.reset(); }
  // Forgets the object's first area: the next start() sets depth 1 afresh.
  void forget() { area0_ = 0; }
  // The frames changed size by `factor` in area: depth goes on from the first area in the new
  // frame's pixels.
  void rescale_area(double factor) { area0_ *= factor; }

  const Pose& pose() const { return pose_; }  // smoothed when TrackerParams::smoothing
  const Pose& raw() const { return raw_; }
  bool pushed() const { return pushed_; }  // a push completed on the last update

 private:
  double area0_ = 0;
  Pose pose_, raw_;
  bool pushed_ = false;
  OneEuroFilter fx_, fy_, fdepth_;
  PushDetector push_;
};

}  // namespace projtrack
