// Push gestures: a quick approach and return is one click; moving closer is none.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "projtrack/push_detector.hpp"

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

// Feeds a box of 100 × 100 px scaled by `sx`(t), `sy`(t), and the depth of its area, at 30 fps.
template <class ScaleX, class ScaleY>
int box_pushes(ScaleX sx, ScaleY sy, double seconds) {
  PushDetector d;
  int count = 0;
  for (int i = 0; i < seconds * 30; ++i) {
    const double t = i / 30.0, w = 100 * sx(t), h = 100 * sy(t);
    count += d.update(std::sqrt(w * h) / 100, w, h, t);
  }
  return count;
}

TEST(PushDetector, APushScalesTheWholeBoxAWidthAloneIsNone) {
  const auto scaled = [](double t) { return 1.0 + bump(t, 1.0, 0.4, 0.3); };
  const auto same = [](double) { return 1.0; };
  // Nearing the camera scales both sides: a push.
  EXPECT_EQ(box_pushes(scaled, scaled, 3.0), 1);
  // Legs opening widen the box, its height stays: the same depth bump is no push.
  const auto wider = [](double t) { return 1.0 + bump(t, 1.0, 0.4, 0.7); };
  EXPECT_EQ(box_pushes(wider, same, 3.0), 0);
  EXPECT_EQ(box_pushes(same, wider, 3.0), 0);
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

TEST(PushDetector, NoPushBeforeTheRestingDepthIsKnown) {
  PushDetector d;  // a push starting 0.1 s into the track
  EXPECT_EQ(pushes(
                d, [](double t) { return 1.0 + bump(t, 0.1, 0.3, 0.3); }, 2.0),
            0);
}

TEST(PushDetector, ANoisyTrackNeedsAClearerPush) {
  // Depth jittering by 5 % at rest, a 12 % bump: a push by the threshold alone, within the
  // track's own noise once the jitter counts.
  const auto count = [](double jitter_factor) {
    PushDetector d;
    PushDetector::Params p;
    p.jitter_factor = jitter_factor;
    d.set_params(p);
    return pushes(
        d, [](double t) { return 1.0 + bump(t, 2.0, 0.4, 0.12); }, 4.0, 0.05);
  };
  EXPECT_GE(count(0.0), 1);
  EXPECT_EQ(count(PushDetector::Params{}.jitter_factor), 0);
}

}  // namespace
}  // namespace projtrack
