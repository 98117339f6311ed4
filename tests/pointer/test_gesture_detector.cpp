// Gestures from depth: pushes, presses and releases are found against the depth's slow trend,
// whatever it drifts, and nothing else is: not a drift, a jump, a widening, noise.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "pointer/gesture_detector.hpp"

namespace projtrack {
namespace {

constexpr double kFps = 30;

struct Event {
  Gesture g;
  double t;
};

// Feeds a 100 × 100 px box scaled by scale(t) (its width by scale(t) · widen(t)) and its depth
// at 30 fps for `seconds`, with multiplicative Gaussian noise; returns the gestures.
std::vector<Event> run(GestureDetector& d, const std::function<double(double)>& scale,
                       double seconds, double noise = 0.005,
                       const std::function<double(double)>& widen = nullptr) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0, noise);
  std::vector<Event> out;
  for (int i = 0; i < seconds * kFps; ++i) {
    const double t = i / kFps, s = scale(t) * (1 + n(rng));
    const double w = 100 * s * (widen ? widen(t) : 1.0), h = 100 * s;
    const Gesture g = d.update(std::sqrt(w * h) / 400, w, h, t);
    if (g != Gesture::None) out.push_back({g, t});
  }
  return out;
}

std::vector<Event> run(const std::function<double(double)>& scale, double seconds,
                       double noise = 0.005) {
  GestureDetector d;
  return run(d, scale, seconds, noise);
}

// A push: +`depth` as a raised cosine over `duration` s from `start`.
double push(double t, double start, double duration, double depth) {
  const double u = (t - start) / duration;
  return u <= 0 || u >= 1 ? 0.0 : depth * (1 - std::cos(2 * M_PI * u)) / 2;
}

// A press: up over 0.2 s from `start`, held `hold` s, down over 0.2 s.
double press(double t, double start, double hold, double depth) {
  const double u = t - start;
  if (u <= 0 || u >= hold + 0.4) return 0.0;
  const double w = u < 0.2 ? u / 0.2 : u < 0.2 + hold ? 1.0 : 1 - (u - 0.2 - hold) / 0.2;
  return depth * (1 - std::cos(M_PI * w)) / 2;
}

// The slow drift of a hand pointing: ±30 % over eight seconds.
double drift(double t) { return 1 + 0.3 * std::sin(2 * M_PI * t / 8); }

TEST(GestureDetector, AQuickPushIsOnePushAtItsPeak) {
  for (double duration : {0.15, 0.3, 0.6}) {
    for (double depth : {0.15, 0.5}) {
      const auto e = run([&](double t) { return 1 + push(t, 2.0, duration, depth); }, 4.0);
      ASSERT_EQ(e.size(), 1u) << duration << " s, +" << depth;
      EXPECT_EQ(e[0].g, Gesture::Push);
      EXPECT_NEAR(e[0].t, 2.0 + duration / 2, 0.3) << duration << " s, +" << depth;
    }
  }
}

TEST(GestureDetector, ADoubleClickIsTwoPushes) {
  const auto e =
      run([](double t) { return 1 + push(t, 2.0, 0.2, 0.3) + push(t, 2.4, 0.2, 0.3); }, 4.0);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].g, Gesture::Push);
  EXPECT_EQ(e[1].g, Gesture::Push);
}

TEST(GestureDetector, AHeldPushIsAPressThenARelease) {
  const auto e = run([](double t) { return 1 + press(t, 2.0, 1.5, 0.25); }, 5.0);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].g, Gesture::Press);
  EXPECT_NEAR(e[0].t, 2.2, 0.4);  // forward at 2.2 s
  EXPECT_EQ(e[1].g, Gesture::Release);
  EXPECT_NEAR(e[1].t, 3.9, 0.3);  // back at 4.1 s, half way at 3.8 s
}

TEST(GestureDetector, ADriftIsNoGestureAndGesturesOnItAreFound) {
  EXPECT_TRUE(run(drift, 16.0).empty());
  // The same drift with a push where it falls fastest and a press where it turns.
  const auto e = run(
      [](double t) { return drift(t) * (1 + push(t, 3.7, 0.45, 0.2) + press(t, 5.8, 1.2, 0.2)); },
      10.0);
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].g, Gesture::Push);
  EXPECT_EQ(e[1].g, Gesture::Press);
  EXPECT_EQ(e[2].g, Gesture::Release);
}

TEST(GestureDetector, OneFramesJumpIsNoGesture) {
  // A leak for one frame, then a step that stays (a re-acquired fragment, a shot cut).
  EXPECT_TRUE(run([](double t) { return std::abs(t - 2.0) < 0.01 ? 1.4 : 1.0; }, 4.0).empty());
  EXPECT_TRUE(run([](double t) { return t < 2.0 ? 1.0 : 1.4; }, 4.0).empty());
}

TEST(GestureDetector, AWidthAloneIsNoGesture) {
  // A walker's legs opening: the box widens, its height stays; the same area change as a push.
  GestureDetector d;
  const auto e = run(
      d, [](double) { return 1.0; }, 4.0, 0.005,
      [](double t) { return 1 + 2 * push(t, 2.0, 0.3, 0.3); });
  EXPECT_TRUE(e.empty());
}

TEST(GestureDetector, ANoisyTrackNeedsAClearerPush) {
  const auto bumps = [](double t) { return 1 + push(t, 2.0, 0.3, 0.15) + push(t, 4.0, 0.3, 0.15); };
  EXPECT_EQ(run(bumps, 6.0, 0.005).size(), 2u);  // quiet: both pushes
  EXPECT_TRUE(run(bumps, 6.0, 0.04).empty());    // 4 % noise: 5 × the noise is above +15 %
}

TEST(GestureDetector, NothingBeforeTheTrendIsKnown) {
  EXPECT_TRUE(run([](double t) { return 1 + push(t, 0.1, 0.3, 0.4); }, 2.0).empty());
}

TEST(GestureDetector, ARestartReleasesAPressAndARefusalDropsARise) {
  GestureDetector d;
  const auto held = run(
      d, [](double t) { return 1 + press(t, 2.0, 5.0, 0.3); }, 3.5);
  ASSERT_EQ(held.size(), 1u);
  EXPECT_EQ(held[0].g, Gesture::Press);
  EXPECT_EQ(d.restart(), Gesture::Release);
  EXPECT_EQ(d.restart(), Gesture::None);
  // A rise cut by a refused frame is no gesture, whatever follows.
  GestureDetector r;
  int pushes = 0;
  for (int i = 0; i < 4 * kFps; ++i) {
    const double t = i / kFps, s = 1 + push(t, 2.0, 0.3, 0.4);
    if (i == 62) r.refuse();
    pushes += r.update(s / 4, 100 * s, 100 * s, t) == Gesture::Push;
  }
  EXPECT_EQ(pushes, 0);
}

TEST(GestureDetector, TimeGoingBackDoesNotMakeGestures) {
  GestureDetector d;
  int gestures = 0;
  for (int i = 0; i < 6 * kFps; ++i) {
    const double t = i < 90 ? i / kFps : (i - 60) / kFps;  // a seek back 2 s at 3 s
    gestures += d.update(0.25, 100, 100, t) != Gesture::None;
  }
  EXPECT_EQ(gestures, 0);
}

TEST(GestureName, NamesEveryGesture) {
  EXPECT_EQ(gesture_name(Gesture::Push), "push");
  EXPECT_EQ(gesture_name(Gesture::Press), "press");
  EXPECT_EQ(gesture_name(Gesture::Release), "release");
  EXPECT_EQ(gesture_name(Gesture::None), "");
}

}  // namespace
}  // namespace projtrack
