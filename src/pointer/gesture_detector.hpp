// Gestures from a track's depth: a small state machine against the depth's slow trend.
#pragma once

#include <cmath>
#include <vector>

#include "pointer/depth_trend.hpp"
#include "projtrack/gesture.hpp"
#include "projtrack/sample_clock.hpp"

namespace projtrack {

// Rest → rising → forward → (back: a push | held: a press … release) → returning → rest.
// Everything is measured in ln depth against the trend (DepthTrend) of the depth at rest, with
// the thresholds of GestureParams scaled by the track's own noise; the box of the object must
// grow with its depth (nearing the camera scales the whole projection; a leak or a walker's
// legs opening do not).
class GestureDetector {
 public:
  void set_params(const GestureParams& p) { p_ = p; }
  // One accepted estimate: the relative depth (any scale: only its changes count), the object's
  // box sides (NaN: not checked), at `t` s. Returns the gesture it completes, if any.
  Gesture update(double depth, double width, double height, double t);
  // A refused frame: a rise in progress is dropped (a press stays held through it).
  void refuse();
  // The track starts afresh (a new object, or the object found again after a loss): everything
  // is forgotten. Returns Gesture::Release when a press was held, else Gesture::None.
  Gesture restart();

 private:
  enum class State { Rest, Rising, Forward, Pressed, Returning };
  struct Sample {
    double t, v;    // s, ln depth
    double lw, lh;  // ln of the box's sides (NaN: unknown)
  };
  // The gesture in progress: the trend it left, frozen, and how far it rose above it.
  struct Rise {
    TrendLine line;
    double theta = 0;  // the threshold, ln depth
    double t_enter = 0, t_forward = 0;
    double level0 = 0;                  // the depth it left (ln), for a press's own rise
    double before_t = 0, before_r = 0;  // the last sample at rest, against the line
    double peak = 0, peak_lw = NAN, peak_lh = NAN;
    double rest_lw = NAN, rest_lh = NAN;
    double speed = 0;                 // of the rise to forward, ln depth / s
    double last_r = 0, max_step = 0;  // the last sample; the largest one-frame rise
    int above = 0;                    // samples above theta
    std::vector<Sample> samples;      // since it entered, for the trend if it is none
    std::vector<Sample> forward;      // (t, r) since forward, for a press's plateau
  };

  Gesture at_rest(const Sample& s);
  Gesture rising(const Sample& s);
  Gesture held(const Sample& s);
  Gesture pressed_step(const Sample& s);
  void returning(const Sample& s);
  void turn_back(const Sample& s, const TrendLine& line, double theta);
  bool scaled() const;
  bool plateau(double t);
  void enter(const Sample& s, const TrendLine& line);
  void back_to_rest();
  void start_again();

  GestureParams p_;
  State state_ = State::Rest;
  bool started_ = false;
  SampleClock clock_;
  DepthTrend trend_;
  double noise_ = NAN;         // the track's noise at rest (ln depth), NaN until measured
  double slope_ = 0;           // the trend's last measured slope
  double t_gesture_ = -1e300;  // the last push's end: a second one may follow at once
  Sample last_rest_{0, 0, NAN, NAN};
  Rise rise_;
  double hold_rise_ = 0;      // a press's rise, ln depth
  std::vector<Sample> hold_;  // while pressed, the last `hold` + guard s
  // Returning: the line it falls back toward, the last sample against it, when it turned back,
  // the last two samples (the level the trend starts again from).
  TrendLine back_line_;
  double back_r_ = 0, back_theta_ = 0, t_back_ = 0;
  std::vector<Sample> back_tail_;
  // Working space kept between frames: once warm, no frame allocates.
  std::vector<TimedValue> timed_;
  std::vector<double> scratch_;
};

}  // namespace projtrack
