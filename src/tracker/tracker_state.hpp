// Everything the tracker keeps from one frame to the next but the object model's own memory, in
// one place, and the named transitions that are the only ways the track changes: the track
// (core/track.hpp) and the pointer's filters. The object model (src/models/) is held beside it by
// the tracker, which tells it each transition (tracker_impl.hpp).
#pragma once

#include <opencv2/core.hpp>

#include "core/track.hpp"
#include "pointer/pointer.hpp"
#include "projtrack/features.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

class TrackerState {
 public:
  const Track& track() const { return track_; }

  Pointer pointer;

  // The user's point or box: a new object, tracked from there on the next frame.
  void seed(Point2i p);
  void seed_box(const Rect& box);
  // The user's mask (CV_8U, frame size, non-zero on the object), with its box and deepest point.
  void seed_mask(const cv::Mat& mask, const Rect& box, Point2i deepest);
  // Forgets the object: acquisition starts over.
  void reset() { drop(); }
  // Ends the track (a press held is released), remembering where the object was (lost_area,
  // lost_centroid).
  void drop();
  // Another object model: the same object (the user's start, if any) found again its own way.
  void switch_model();
  // Takes `f` as this frame's estimate, at `t` seconds in a width × height frame; `resumed`: the
  // object found again by its model. True when a track (re)starts here.
  bool accept(const Features& f, bool resumed, double t, int width, int height,
              const TrackerParams& tp);
  // One more refused frame: the last accepted estimate stays; a gesture in progress does not.
  void refuse();
  // The object is lost, but the track goes on (its model looks for it again where it was): the
  // refusals in a row count afresh, a press held is released; its last estimate and start stay.
  void lose() {
    track_.refused_in_a_row = 0;
    pointer.end();
  }
  // The object is hidden by another on this frame: the last accepted estimate stays, a gesture in
  // progress does not, and the frame does not count towards dropping the track.
  void hide() { pointer.refuse(); }
  // The frames are now sx × sy times as large, width × height: the track's points, boxes and
  // areas follow (the boxes within the frame).
  void rescale(double sx, double sy, int width, int height);
  // The object model starts again within the last box on the next frame (its colours no longer
  // hold, or it could not follow a rescale); the track (its last estimate, its inner point, the
  // pointer) goes on, so that start is no new acquisition.
  void restart_within_last_box();
  // The frames' colours are read another way: the centroid's step across it is no velocity.
  void mark_across_change() { track_.across_change = true; }

 private:
  Track track_;
};

}  // namespace projtrack
