// The 3D pointer: x and y from the centroid, depth from the area, smoothed, with gestures.
#pragma once

#include "pointer/gesture_detector.hpp"
#include "pointer/one_euro_filter.hpp"
#include "projtrack/features.hpp"
#include "projtrack/gesture.hpp"
#include "projtrack/pose.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

// Depth is one rule, the same however the track started and whatever came before:
// √(area ÷ the frame's area) (pose.hpp). It holds no reference to reset, so it goes on through
// a loss and a re-acquisition as the object's size does.
double depth_of(double area, int width, int height);

class Pointer {
 public:
  // A track starts (a new object, or the same found again): the smoothing and the gesture
  // detector start afresh; a press held is released.
  void restart();
  // One accepted estimate at `t` seconds in a width × height frame.
  void update(const Features& f, int width, int height, double t, const TrackerParams& tp);
  // A refused frame: a gesture rising is dropped; a press stays held.
  void refuse() { gestures_.refuse(); }
  // The track ends (dropped, or the tracker reset): a press held is released.
  void end();
  // The gesture of the frame (what update, refuse, end or restart completed since the last
  // call), once: the frame's result takes it.
  Gesture take_gesture();

  const Pose& pose() const { return pose_; }  // smoothed when TrackerParams::smoothing
  const Pose& raw() const { return raw_; }

 private:
  void note(Gesture g);

  Pose pose_, raw_;
  Gesture gesture_ = Gesture::None;
  OneEuroFilter fx_, fy_, fdepth_;
  GestureDetector gestures_;
};

}  // namespace projtrack
