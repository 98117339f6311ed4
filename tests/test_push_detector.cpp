// Push gestures: a quick approach and return is one click; moving closer is none.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "push_detector.hpp"

namespace projtrack {
namespace {

// Feeds depth(t) at 30 fps for `seconds`; counts pushes.
template <class Depth>
int pushes(PushDetector& d, Depth depth, double seconds, double noise = 0) {
  std::mt19937 rng(2);
  std::normal_distribution<double> n(0, noise);
  int count = 0;
  for (int i = 0; i < seconds * 30; ++i) {
    const double t = i / 30.0;
    count += d.update(depth(t) * (1 + (noise > 0 ? n(rng) : 0)), t);
  }
  return count;
}

double bump(double t, double start, double width, double height) {
  const double u = (t - start) / width;
  return u < 0 || u > 1 ? 0 : height * std::sin(M_PI * u);
}

TEST(PushDetector, AQuickPushAndReturnIsExactlyOneGesture) {
  PushDetector d;
  EXPECT_EQ(pushes(
                d, [](double t) { return 1.0 + bump(t, 1.0, 0.4, 0.3); }, 3.0),
            1);
}

TEST(PushDetector, TwoPushesAreTwo) {
  PushDetector d;
  const auto depth = [](double t) { return 1.0 + bump(t, 1.0, 0.4, 0.3) + bump(t, 2.5, 0.4, 0.3); };
  EXPECT_EQ(pushes(d, depth, 4.0), 2);
}

TEST(PushDetector, MovingCloserAndStayingIsNotAPush) {
  PushDetector d;
  EXPECT_EQ(pushes(
                d, [](double t) { return t < 1 ? 1.0 : std::min(1.5, 1.0 + (t - 1)); }, 5.0),
            0);
}

TEST(PushDetector, ASlowPushIsNotAClick) {
  PushDetector d;
  EXPECT_EQ(pushes(
                d, [](double t) { return 1.0 + bump(t, 0.5, 2.5, 0.3); }, 4.0),
            0);
}

TEST(PushDetector, TimeGoingBackwardsDoesNotStretchLaterPushes) {
  PushDetector d;
  int count = 0;
  for (int i = 0; i < 120; ++i) count += d.update(1.0, 5.0 + i / 60.0);  // 60 fps, then a seek
  for (int i = 0; i < 180; ++i) {
    const double t = i / 60.0;
    count += d.update(1.0 + bump(t, 1.0, 0.6, 0.3), t);
  }
  EXPECT_EQ(count, 1);
}

TEST(PushDetector, SmallAndNoisyChangesAreNotPushes) {
  PushDetector d;
  EXPECT_EQ(pushes(
                d, [](double t) { return 1.0 + bump(t, 1.0, 0.4, 0.06); }, 3.0, 0.02),
            0);
}

}  // namespace
}  // namespace projtrack
