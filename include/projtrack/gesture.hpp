// The gestures of the 3D mouse: what a change of depth means (docs/tracker.md, "Gestures").
#pragma once

#include <string_view>

namespace projtrack {

// What the object's depth did, reported on the frame it became known.
enum class Gesture {
  None,
  Push,     // forward and back quickly: a click (two quick pushes are two clicks)
  Press,    // forward and held there: the button goes down (a drag while it moves in x and y)
  Release,  // back after a press, or the track ended while pressed: the button comes up
};

// "push", "press", "release"; empty for Gesture::None.
std::string_view gesture_name(Gesture g);

// How gestures are told from the rest of the depth's motion. A gesture is measured against the
// slow trend of depth (a robust line through the depth at rest over the last `trend_window`
// seconds, ln depth against time), never against one frame: a rise above that trend by more
// than `threshold` and by more than `noise_factor` × the track's own noise (the scatter of the
// depth about its trend, a median absolute deviation) is a gesture's start.
struct GestureParams {
  // The least rise of depth over its trend a gesture makes, relative: 0.07 = 7 % (half the
  // shallowest push a hand makes on purpose, +15 %: docs/pointer.md).
  double threshold = 0.07;
  // A gesture must also rise this many times the track's noise above the trend: a noisy track
  // (a small or ragged object) needs a clearer gesture.
  double noise_factor = 5.0;
  // s: the trend is a line through the depth at rest over this long (drift, a hand drifting
  // toward and away from the camera, is followed; a gesture, faster, is not).
  double trend_window = 0.7;
  // s: the newest depth the trend leaves out, so that a gesture's first frames do not tilt it.
  double trend_guard = 0.1;
  // s: the trend needs depth at rest over this long before any gesture (a new track's first
  // moments, or after a gesture: then only a second push of a double click is looked for).
  double settle = 0.4;
  // s: a gesture goes from half the threshold to the threshold within this (a drift the trend
  // missed rises slower).
  double max_rise = 0.15;
  // s: forward for longer than this is a press; back sooner, a push. A push of up to 0.6 s is
  // forward (above half its rise) for at most 0.3 s.
  double hold = 0.4;
  // Frames above the threshold a gesture needs: one frame's jump (a leak, a shot cut) is none.
  int min_frames = 2;
};

}  // namespace projtrack
