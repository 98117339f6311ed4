// The One Euro filter: less jitter at rest, little lag in motion.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pointer/one_euro_filter.hpp"

namespace projtrack {
namespace {

TEST(OneEuroFilter, RemovesJitterAtRest) {
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0, 0.01);
  OneEuroFilter f;
  double raw2 = 0, out2 = 0;
  for (int i = 0; i < 300; ++i) {
    const double x = 0.3 + noise(rng);
    const double y = f.filter(x, i / 30.0);
    if (i > 30) raw2 += (x - 0.3) * (x - 0.3), out2 += (y - 0.3) * (y - 0.3);
  }
  EXPECT_LT(std::sqrt(out2), std::sqrt(raw2) / 3);  // measured: about 5× less
}

TEST(OneEuroFilter, FollowsFastMotionWithLittleLag) {
  OneEuroFilter smooth, stiff;
  smooth.set_params({1.0, 0.5, 1.0});
  stiff.set_params({1.0, 0.0, 1.0});
  double lag_smooth = 0, lag_stiff = 0;
  for (int i = 0; i < 30; ++i) {  // a sweep across the frame in one second
    const double x = -1 + 2.0 * i / 29;
    lag_smooth = x - smooth.filter(x, i / 30.0);
    lag_stiff = x - stiff.filter(x, i / 30.0);
  }
  EXPECT_LT(lag_smooth, 0.5 * lag_stiff);  // beta raises the cutoff with speed
  EXPECT_LT(lag_smooth, 0.15);
}

TEST(OneEuroFilter, StartsAtTheFirstSampleAndSurvivesTimeThatDoesNotAdvance) {
  OneEuroFilter f;
  EXPECT_EQ(f.filter(0.7, 5.0), 0.7);
  const double y = f.filter(0.8, 5.0);  // same timestamp: taken as one frame later
  EXPECT_TRUE(std::isfinite(y));
  EXPECT_GT(y, 0.7);
  EXPECT_LT(y, 0.8);
  f.reset();
  EXPECT_EQ(f.filter(-0.2, 0.0), -0.2);
}

}  // namespace
}  // namespace projtrack
