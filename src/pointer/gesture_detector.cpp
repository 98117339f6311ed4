#include "pointer/gesture_detector.hpp"

#include <algorithm>
#include <vector>

namespace projtrack {

namespace {

// A rise (or fall) of which one frame carries more than this share is a jump (a leak, a shot
// cut, a re-acquired fragment), not a hand's motion: a press rises over several frames (at 30
// fps a 0.15 s rise puts at most 35 % in one), a push at least rises or falls over two (a
// 0.15 s push puts at most 72 % of both its rise and its fall in one frame; 88 % at 25 fps).
constexpr double kPressJump = 2.0 / 3;
constexpr double kPushJump = 0.9;

double log_or_nan(double x) { return x > 0 && std::isfinite(x) ? std::log(x) : NAN; }

// The samples of `from` at or after `since` as (t, v) into `out`.
template <class Samples>
const std::vector<TimedValue>& timed(const Samples& from, double since,
                                     std::vector<TimedValue>& out) {
  out.clear();
  for (const auto& x : from)
    if (x.t >= since) out.push_back({x.t, x.v});
  return out;
}

// Drops the samples older than `oldest` from the front of `v` (never allocates).
template <class Samples>
void drop_before(Samples& v, double oldest) {
  auto it = v.begin();
  while (it != v.end() && it->t < oldest) ++it;
  v.erase(v.begin(), it);
}

}  // namespace

Gesture GestureDetector::update(double depth, double width, double height, double t) {
  const double v = log_or_nan(depth);
  if (!std::isfinite(v)) return Gesture::None;
  if (!started_) {
    started_ = true;
    clock_.start(t);
  } else {
    clock_.step(t);
  }
  const Sample s{clock_.now(), v, log_or_nan(width), log_or_nan(height)};
  switch (state_) {
    case State::Pressed:
      return pressed_step(s);
    case State::Returning:
      returning(s);
      return state_ == State::Rest ? at_rest(s) : Gesture::None;
    case State::Rest:
      return at_rest(s);
    case State::Rising:
    case State::Forward:
      return rising(s);
  }
  return Gesture::None;
}

// At rest: the sample joins the trend, or starts a rise above it.
Gesture GestureDetector::at_rest(const Sample& s) {
  std::optional<TrendLine> line = trend_.fit(s.t, p_.trend_guard, p_.settle);
  if (line) {
    noise_ = line->noise;
    slope_ = line->slope;
  } else if (std::isfinite(noise_) && s.t - t_gesture_ <= p_.hold + p_.max_rise) {
    line = trend_.level(slope_);  // just after a push: a double click's second one
  }
  if (!line || !std::isfinite(noise_) ||
      s.v - line->at(s.t) <= std::max(std::log1p(p_.threshold), p_.noise_factor * noise_) / 2) {
    trend_.add(s.t, s.v, p_.trend_window, p_.trend_guard);
    last_rest_ = s;
    return Gesture::None;
  }
  enter(s, *line);  // a level's noise is NaN: only a fitted line can tell a press from a drift
  return rising(s);
}

void GestureDetector::enter(const Sample& s, const TrendLine& line) {
  state_ = State::Rising;
  std::vector<Sample> samples = std::move(rise_.samples), forward = std::move(rise_.forward);
  samples.clear();
  forward.clear();
  rise_ = Rise{};  // its buffers kept, emptied: a gesture allocates nothing once warm
  rise_.samples = std::move(samples);
  rise_.forward = std::move(forward);
  rise_.line = line;
  rise_.theta = std::max(std::log1p(p_.threshold), p_.noise_factor * noise_);
  rise_.t_enter = s.t;
  rise_.level0 = trend_.size() ? trend_.recent() : s.v;
  const Sample& before = trend_.size() ? last_rest_ : s;
  rise_.before_t = before.t;
  rise_.before_r = rise_.last_r = before.v - line.at(before.t);
  rise_.peak = -HUGE_VAL;
  rise_.rest_lw = last_rest_.lw;
  rise_.rest_lh = last_rest_.lh;
}

// Rising or forward: how far above the trend it left, and whether it came back or held.
Gesture GestureDetector::rising(const Sample& s) {
  Rise& k = rise_;
  const double r = s.v - k.line.at(s.t);
  k.samples.push_back(s);
  const double step = r - std::max(k.last_r, 0.0);  // from the trend: a dip adds nothing
  k.last_r = r;
  if (r > k.peak)
    k.peak = r, k.peak_lw = s.lw, k.peak_lh = s.lh, k.max_step = std::max(k.max_step, step);
  if (r >= k.theta) ++k.above;
  if (state_ == State::Rising) {
    if (r >= k.theta) {
      state_ = State::Forward;
      k.t_forward = s.t;
      k.speed = (r - k.before_r) / std::max(s.t - k.before_t, 1e-3);
    } else {
      if (s.t - k.t_enter > p_.max_rise || r < k.theta / 4) back_to_rest();  // too slow: drift
      return Gesture::None;
    }
  }
  k.forward.push_back({s.t, r, NAN, NAN});
  return held(s);
}

// Forward: back below half its rise is a push; held past `hold` on a plateau, a press.
Gesture GestureDetector::held(const Sample& s) {
  Rise& k = rise_;
  const double r = k.forward.back().v;
  const bool enough = k.above >= p_.min_frames && scaled();
  if (r < k.peak / 2) {
    const double fell =
        (k.forward.size() > 1 ? k.forward[k.forward.size() - 2].v : k.peak) - std::max(r, 0.0);
    const bool leak = k.max_step > kPushJump * k.peak && fell > kPushJump * k.peak;
    if (!enough || leak) {  // one frame's jump, or a box that did not scale: no gesture
      back_to_rest();
      return Gesture::None;
    }
    turn_back(s, k.line, k.theta);
    t_gesture_ = s.t;
    return Gesture::Push;
  }
  if (s.t - k.t_forward <= p_.hold) return Gesture::None;
  // A press rose by itself (not only against a trend that fell away), from a fitted trend, and
  // then stays: its depth changes at least twice as slowly as it rose.
  const double own = s.v - k.level0;
  if (enough && own >= k.theta && std::isfinite(k.line.noise) && plateau(s.t) &&
      k.max_step <= kPressJump * k.peak) {
    state_ = State::Pressed;
    hold_rise_ = std::min(k.peak, own);
    hold_.clear();  // the plateau so far: the forward samples of the last `hold` / 2
    for (const Sample& f : k.samples)
      if (f.t >= s.t - p_.hold / 2) hold_.push_back(f);
    return Gesture::Press;
  }
  back_to_rest();  // it rose slowly and stayed: the depth moved, no gesture
  return Gesture::None;
}

bool GestureDetector::plateau(double t) {
  const std::vector<TimedValue>& late = timed(rise_.forward, t - p_.hold / 2, timed_);
  return late.size() >= 3 && 2 * std::abs(least_squares(late).slope) <= rise_.speed;
}

bool GestureDetector::scaled() const {
  const Rise& k = rise_;
  if (!std::isfinite(k.rest_lw + k.rest_lh + k.peak_lw + k.peak_lh)) return true;
  // Nearing the camera scales both sides as much as the depth; a third of it is asked (a
  // silhouette is ragged, may be cut by the frame's edge): a widening alone shows none.
  return k.peak_lw - k.rest_lw >= k.peak / 3 && k.peak_lh - k.rest_lh >= k.peak / 3;
}

// Pressed: released when the depth falls by half the press's rise below where it is held: a
// line through the depth held over the last `hold` s (older than the trend's guard, so that
// the fall does not tilt it), since a drift goes on while a press is held.
Gesture GestureDetector::pressed_step(const Sample& s) {
  hold_.push_back(s);
  drop_before(hold_, s.t - p_.hold - p_.trend_guard);
  timed_.clear();
  for (const Sample& h : hold_)
    if (h.t <= s.t - p_.trend_guard) timed_.push_back({h.t, h.v});
  if (timed_.size() < 3) return Gesture::None;
  const TrendLine line = median_line(timed_, least_squares(timed_).slope, scratch_);
  if (s.v >= line.at(s.t) - hold_rise_ / 2) return Gesture::None;
  turn_back(s, line, hold_rise_);
  return Gesture::Release;
}

void GestureDetector::turn_back(const Sample& s, const TrendLine& line, double theta) {
  state_ = State::Returning;
  back_line_ = line;
  back_r_ = s.v - line.at(s.t);
  back_theta_ = theta;
  t_back_ = s.t;
  back_tail_.clear();
  back_tail_.push_back(s);
}

// After a gesture, while the depth falls back toward the line it left (or it was held on):
// neither rest nor a gesture. Once it stops falling against that line, comes near it, or after
// `hold`, the trend starts again from the level it came back to (the noise stays known).
void GestureDetector::returning(const Sample& s) {
  const double r = s.v - back_line_.at(s.t);
  const bool falling = r < back_r_ && r >= back_theta_ / 4;
  back_r_ = r;
  if (falling && s.t - t_back_ <= p_.hold) {
    back_tail_.push_back(s);
    if (back_tail_.size() > 2) back_tail_.erase(back_tail_.begin());
    return;
  }
  start_again();
  for (const Sample& x : back_tail_) trend_.add(x.t, x.v, p_.trend_window, p_.trend_guard);
}

void GestureDetector::back_to_rest() {
  state_ = State::Rest;
  for (const Sample& x : rise_.samples) trend_.add(x.t, x.v, p_.trend_window, p_.trend_guard);
  if (!rise_.samples.empty()) last_rest_ = rise_.samples.back();
}

void GestureDetector::start_again() {
  trend_.clear();
  state_ = State::Rest;
}

void GestureDetector::refuse() {
  if (state_ == State::Rising || state_ == State::Forward) start_again();
}

Gesture GestureDetector::restart() {
  const bool was_pressed = state_ == State::Pressed;
  start_again();
  noise_ = NAN;
  slope_ = 0;
  t_gesture_ = -1e300;
  started_ = false;
  return was_pressed ? Gesture::Release : Gesture::None;
}

}  // namespace projtrack
