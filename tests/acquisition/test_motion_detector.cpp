// Frame differencing: which samples changed, and how many grey levels a scene spans (the tracker
// scales its grey-level thresholds to it, so a dim scene's smaller changes still count).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "acquisition/motion_detector.hpp"
#include "acquisition/motion_gate.hpp"

namespace projtrack {
namespace {

struct Gray {
  int width, height;
  std::vector<std::uint8_t> pixels;
  Gray(int w, int h, std::uint8_t v) : width(w), height(h), pixels(std::size_t(w) * h, v) {}
  std::uint8_t& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  ImageView view() const { return ImageView(pixels.data(), width, height, width); }
};

TEST(MotionDetector, TheChangedSamplesAfterTheFirstFrame) {
  MotionDetector d;
  MotionDetector::Motion m;
  Gray a(64, 48, 100), b = a;
  for (int y = 10; y < 20; ++y)
    for (int x = 30; x < 40; ++x) b.at(x, y) = 100 + 40;  // changed by more than the threshold
  b.at(2, 2) = 100 + 10;                                  // by less
  EXPECT_FALSE(d.update(a.view(), {}, m));                // nothing to compare with yet
  ASSERT_TRUE(d.update(b.view(), {}, m));
  EXPECT_EQ(m.points.size(), 25u);  // step 2: 5 × 5 samples of the 10 × 10 square
  EXPECT_NEAR(m.centroid.x, 34, 1e-9);
  EXPECT_NEAR(m.centroid.y, 14, 1e-9);
  MotionDetector::Params strict;
  strict.threshold = 50;
  ASSERT_TRUE(d.update(a.view(), strict, m));
  EXPECT_TRUE(m.points.empty());
}

// Noise changes every other sample at random (what the detector lists without branching on it),
// on odd sizes and steps: the samples are those a plain reading finds, row by row (the finder
// relies on the order), with the fraction and centroid they give.
TEST(MotionDetector, OnNoiseTheChangedSamplesAreThoseAPlainReadingFindsRowByRow) {
  std::mt19937 rng(7);
  for (const int step : {1, 3, 4}) {
    Gray a(61, 47, 0), b = a;
    for (auto* g : {&a, &b})
      for (auto& v : g->pixels) v = static_cast<std::uint8_t>(rng() % 256);
    MotionDetector::Params p;
    p.step = step;
    MotionDetector d;
    MotionDetector::Motion m;
    d.update(a.view(), p, m);
    ASSERT_TRUE(d.update(b.view(), p, m));
    std::vector<Point2i> expect;
    for (int y = 0; y < a.height; y += step)
      for (int x = 0; x < a.width; x += step)
        if (std::abs(b.at(x, y) - a.at(x, y)) > p.threshold) expect.push_back({x, y});
    ASSERT_EQ(m.points, expect) << "step " << step;
    const int samples = ((a.width + step - 1) / step) * ((a.height + step - 1) / step);
    EXPECT_DOUBLE_EQ(m.fraction, static_cast<double>(expect.size()) / samples);
    double sx = 0, sy = 0;
    for (const Point2i& q : expect) sx += q.x, sy += q.y;
    EXPECT_NEAR(m.centroid.x, sx / expect.size(), 1e-9);
    EXPECT_NEAR(m.centroid.y, sy / expect.size(), 1e-9);
  }
}

TEST(MotionDetector, TheSpreadOfTheSceneFromThe2ndToThe98thPercentile) {
  MotionDetector d;
  MotionDetector::Motion m;
  EXPECT_EQ(d.spread(), 0);  // no frame yet
  Gray flat(100, 100, 128);
  d.update(flat.view(), {}, m);
  EXPECT_EQ(d.spread(), 0);
  // A ramp over 0–199 with a few outliers at 255: the outliers are outside the percentiles.
  Gray ramp(200, 100, 0);
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 200; ++x) ramp.at(x, y) = static_cast<std::uint8_t>(x);
  for (int x = 0; x < 200; x += 2) ramp.at(x, 0) = 255;
  d.update(ramp.view(), {}, m);
  EXPECT_NEAR(d.spread(), 192, 4);  // from about 4 to about 196
  // The same ramp at half the contrast spans half as many levels.
  for (auto& v : ramp.pixels) v = static_cast<std::uint8_t>(v == 255 ? 255 : 50 + v / 2);
  d.update(ramp.view(), {}, m);
  EXPECT_NEAR(d.spread(), 96, 3);
  d.reset();
  EXPECT_EQ(d.spread(), 0);
}

// Fresh salt noise over the whole frame changes every part of it alike: no part moves apart
// (what automatic acquisition does not search). The same noise with a square that moves on it,
// or a square alone, is not even. Nor is an empty frame.
TEST(MotionGate, NoiseEverywhereChangesEvenlyAMovingSquareDoesNot) {
  std::mt19937 rng(11);
  const auto salt = [&](Gray& g) {
    for (auto& v : g.pixels) v = rng() % 20 == 0 ? 255 : 60;
  };
  Gray a(320, 240, 60), b(320, 240, 60);
  salt(a);
  salt(b);
  MotionDetector d;
  MotionDetector::Motion m;
  d.update(a.view(), {}, m);
  ASSERT_TRUE(d.update(b.view(), {}, m));
  EXPECT_TRUE(changed_evenly(m, 320, 240));
  Gray c(320, 240, 60), e(320, 240, 60);  // fresh noise on each, and a checker that moves
  salt(c);
  salt(e);
  for (int y = 100; y < 160; ++y)
    for (int x = 150; x < 210; ++x) c.at(x, y) = (x / 4 + y / 4) % 2 ? 200 : 20;
  for (int y = 100; y < 160; ++y)
    for (int x = 160; x < 220; ++x) e.at(x, y) = (x / 4 + y / 4) % 2 ? 20 : 200;  // moved on
  MotionDetector d2;
  d2.update(c.view(), {}, m);
  ASSERT_TRUE(d2.update(e.view(), {}, m));
  EXPECT_FALSE(changed_evenly(m, 320, 240)) << "the moving square is denser than the noise";
  Gray f(320, 240, 60), g(320, 240, 60);
  for (int y = 100; y < 160; ++y)
    for (int x = 150; x < 210; ++x) g.at(x, y) = 200;
  MotionDetector d3;
  d3.update(f.view(), {}, m);
  ASSERT_TRUE(d3.update(g.view(), {}, m));
  EXPECT_FALSE(changed_evenly(m, 320, 240)) << "a square alone";
  m.points.clear();
  EXPECT_FALSE(changed_evenly(m, 320, 240)) << "nothing changed";
  EXPECT_FALSE(changed_evenly(m, 0, 0));
}

}  // namespace
}  // namespace projtrack
