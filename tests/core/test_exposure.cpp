// A frame's luma range, the exposure that reads a dim frame as a normal one, and work frames read
// with it.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "projtrack/exposure.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

TEST(Exposure, TheRangeIsThe2ndAnd98thPercentiles) {
  std::array<std::uint32_t, 256> h{};
  h[10] = 1;   // 1 %: below the 2nd percentile
  h[20] = 48;  // the dark half
  h[200] = 50;
  h[250] = 1;  // 1 % above the 98th
  const LumaRange r = luma_range(h);
  EXPECT_EQ(r.lo, 20);
  EXPECT_EQ(r.hi, 200);
  EXPECT_EQ(r.spread(), 180);
  const std::array<std::uint32_t, 256> empty{};
  EXPECT_LE(luma_range(empty).lo, luma_range(empty).hi);
}

TEST(Exposure, ADimFrameIsStretchedToFullLightAndABrightOneLeftAsItIs) {
  EXPECT_TRUE(exposure_for({16, 235}, 140, 190).identity());
  EXPECT_TRUE(exposure_for({100, 170}, 140, 190).identity());  // a bright wall: few levels
  const Exposure dim = exposure_for({5, 100}, 140, 190);
  EXPECT_EQ(dim.black, 5);
  EXPECT_DOUBLE_EQ(dim.gain, 2.0);
  EXPECT_EQ(exposure_for({40, 110}, 140, 190).black, 16);     // black is at most video black
  EXPECT_DOUBLE_EQ(exposure_for({0, 20}, 140, 190).gain, 3);  // more would amplify noise
  EXPECT_TRUE(exposure_for({0, 0}, 140, 190).identity());     // all black: nothing to stretch
  EXPECT_TRUE(exposure_for({0, 40}, 0, 190).identity());      // off
  EXPECT_TRUE(exposure_for({0, 40}, std::nan(""), 190).identity());
  EXPECT_TRUE(exposure_for({0, 40}, 140, std::nan("")).identity());
  EXPECT_TRUE(exposure_for({0, 130}, 140, 100).identity());  // never darker
}

}  // namespace
}  // namespace projtrack
