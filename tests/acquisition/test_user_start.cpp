// The user's point or box is an instruction: the object there is tracked whatever colours the
// frame's border shows, however large the object, and however small (tests/acquisition: the
// seed region, the colour separation that picks between candidates; the tracker end to end).
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "acquisition/seed_region.hpp"
#include "acquisition/separation.hpp"
#include "projtrack/tracker.hpp"

namespace projtrack {
namespace {

// A gray frame: a white wall, a black target of radius 3r held at (cx, cy), a white disc of
// radius r on it, and noise; as a ColorView without chroma (grey footage).
struct GrayFrame {
  cv::Mat gray;
  ColorView view() const { return {ImageView(gray.data, gray.cols, gray.rows, gray.step), {}, {}}; }
};

GrayFrame disc_on_target(int cx, int cy, int r, int w = 320, int h = 240, int seed = 1) {
  GrayFrame f;
  f.gray = cv::Mat(h, w, CV_8U, cv::Scalar(225));
  cv::circle(f.gray, {cx, cy}, 3 * r, cv::Scalar(25), cv::FILLED, cv::LINE_AA);
  cv::circle(f.gray, {cx, cy}, r, cv::Scalar(230), cv::FILLED, cv::LINE_AA);
  cv::Mat noise(f.gray.size(), CV_16S);
  cv::theRNG().state = static_cast<std::uint64_t>(seed);
  cv::randn(noise, 0, 4);
  cv::Mat g16;
  f.gray.convertTo(g16, CV_16S);
  g16 += noise;
  g16.convertTo(f.gray, CV_8U);
  return f;
}

TEST(SeedRegion, GrowsTheRegionOfTheSeedsColourThatStaysTheSameOverMostTolerances) {
  const GrayFrame f = disc_on_target(160, 120, 20);
  SeedRegion region;
  Mask out;
  MaskOps ops;
  ASSERT_TRUE(region.grow(f.view(), {0, 0}, {160, 120}, 1, 0.9 * 320 * 240, out, ops));
  const double disc = M_PI * 20 * 20;
  EXPECT_NEAR(moments(out).area / disc, 1.0, 0.1) << "the disc, not the target or the wall";
  EXPECT_NEAR(moments(out).centroid.x, 160, 1);
  // From the target, the target (its hole, the disc, filled).
  ASSERT_TRUE(region.grow(f.view(), {0, 0}, {160, 160}, 1, 0.9 * 320 * 240, out, ops));
  EXPECT_NEAR(moments(out).area / (9 * disc), 1.0, 0.1);
}

TEST(SeedRegion, RefusesARegionThatReachesAllFourSidesOfTheFrame) {
  const cv::Mat flat(60, 80, CV_8U, cv::Scalar(128));
  const ColorView v{ImageView(flat.data, 80, 60, flat.step), {}, {}};
  SeedRegion region;
  Mask out;
  MaskOps ops;
  EXPECT_FALSE(region.grow(v, {0, 0}, {40, 30}, 1, 80 * 60, out, ops));
}

TEST(ColourSeparation, IsHighForAnObjectUnlikeItsSurroundingsAndLowForAPatchOfTheWall) {
  const GrayFrame f = disc_on_target(160, 120, 20);
  Mask disc, wall, scratch;
  MaskOps ops;
  disc.reset({130, 90, 61, 61});
  wall.reset({10, 10, 41, 41});
  for (int y = 0; y < 61; ++y)
    for (int x = 0; x < 61; ++x) disc.row(y)[x] = std::hypot(x - 30, y - 30) <= 20;
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x) wall.row(y)[x] = std::hypot(x - 20, y - 20) <= 15;
  EXPECT_GT(colour_separation(f.view(), disc, ops, scratch), 0.7);
  EXPECT_LT(colour_separation(f.view(), wall, ops, scratch), 0.2);
}

TrackResult track_disc(Tracker& t, int frame, int cx, int cy, int r, int w = 320, int h = 240) {
  const GrayFrame f = disc_on_target(cx, cy, r, w, h, frame + 1);
  return t.track(f.view().luma, EdgeParams{}, frame / 25.0, Method::GapTolerantFilling, {}, {});
}

// Grey footage whose border is as white as the disc: the user's point on the disc tracks the
// disc (it was refused: "no colour near the inner point that the frame's border does not show").
TEST(UserStart, AWhiteDiscOnABlackTargetBeforeAWhiteWallIsTrackedFromAPointOnIt) {
  Tracker t;
  t.seed({100, 120});
  for (int i = 0; i < 20; ++i) {
    const int cx = 100 + 4 * i;
    const TrackResult r = track_disc(t, i, cx, 120, 15);
    ASSERT_TRUE(has_features(r.status)) << i << ": " << status_name(r.status) << " " << r.detail;
    EXPECT_NEAR(r.features.centroid.x, cx, 2) << i;
    EXPECT_NEAR(r.features.area / (M_PI * 15 * 15), 1.0, 0.2) << i;
  }
}

// The user's object may be most of the picture, and touch its edge.
TEST(UserStart, AnObjectLargerThanHalfTheFrameAndCutByItsEdgeIsTracked) {
  Tracker t;
  t.seed({150, 120});
  for (int i = 0; i < 10; ++i) {
    cv::Mat gray(240, 320, CV_8U, cv::Scalar(30));
    cv::ellipse(gray, {170 + 3 * i, 120}, {190, 100}, 0, 0, 360, cv::Scalar(220), cv::FILLED);
    const TrackResult r = t.track(ImageView(gray.data, 320, 240, gray.step), EdgeParams{}, i / 25.0,
                                  Method::GapTolerantFilling, {}, {});
    ASSERT_TRUE(has_features(r.status)) << i << ": " << r.detail;
    EXPECT_EQ(r.status, TrackStatus::ReachedBorder);
    EXPECT_GT(r.features.area, 0.5 * 320 * 240) << i;
  }
}

// A ball of 12 px across, far under the least share of the frame the tracker takes by itself.
TEST(UserStart, ASmallObjectThePointIsOnIsTracked) {
  Tracker t;
  t.seed({60, 100});
  for (int i = 0; i < 15; ++i) {
    const int cx = 60 + 3 * i;
    const TrackResult r = track_disc(t, i, cx, 100, 6, 640, 480);
    ASSERT_TRUE(has_features(r.status)) << i << ": " << r.detail;
    EXPECT_NEAR(r.features.centroid.x, cx, 2) << i;
  }
}

// The point's colour is the border's (a dark puck; dark bands along the frame's edges), and a
// grey patch the border does not show lies just beside the point. The patch stands further apart
// from its surroundings than the puck (a light mark on it shows the table's colour), but the point
// is on the puck: the puck is the object, not the region found beside the point.
TEST(UserStart, ARegionBesideThePointIsNotTakenForTheObjectUnderIt) {
  Tracker t;
  t.seed({145, 184});
  for (int i = 0; i < 10; ++i) {
    cv::Mat gray(240, 320, CV_8U, cv::Scalar(200));
    cv::rectangle(gray, {0, 0, 320, 12}, cv::Scalar(30), cv::FILLED);
    cv::rectangle(gray, {0, 228, 320, 12}, cv::Scalar(30), cv::FILLED);
    const int cx = 160 + i;
    cv::rectangle(gray, {120, 160, 18, 48}, cv::Scalar(110), cv::FILLED);
    cv::circle(gray, {cx, 184}, 20, cv::Scalar(30), cv::FILLED, cv::LINE_AA);
    cv::circle(gray, {cx + 6, 184}, 8, cv::Scalar(200), cv::FILLED, cv::LINE_AA);
    const TrackResult r = t.track(ImageView(gray.data, 320, 240, gray.step), EdgeParams{}, i / 25.0,
                                  Method::GapTolerantFilling, {}, {});
    ASSERT_TRUE(has_features(r.status)) << i << ": " << status_name(r.status) << " " << r.detail;
    EXPECT_NEAR(r.features.centroid.x, cx, 3) << i;
    EXPECT_NEAR(r.features.area / (M_PI * 20 * 20), 1.0, 0.2) << i;
  }
}

// Without a seed: a dark puck sliding over a light table whose frame edges are as dark. No
// region of colours the border does not show moves; the moving blob is found, and in it the
// puck (it was never acquired: "no moving region of its own colours, wholly in view").
TEST(NoSeed, AnObjectOfTheBordersColoursIsFoundWhereTheFrameMoves) {
  Tracker t;
  int found = -1;
  for (int i = 0; i < 20 && found < 0; ++i) {
    cv::Mat gray(240, 320, CV_8U, cv::Scalar(200));
    cv::rectangle(gray, {0, 0, 320, 12}, cv::Scalar(30), cv::FILLED);
    cv::rectangle(gray, {0, 228, 320, 12}, cv::Scalar(30), cv::FILLED);
    const int cx = 80 + 5 * i;
    cv::circle(gray, {cx, 120}, 20, cv::Scalar(30), cv::FILLED, cv::LINE_AA);
    const TrackResult r = t.track(ImageView(gray.data, 320, 240, gray.step), EdgeParams{}, i / 25.0,
                                  Method::GapTolerantFilling, {}, {});
    if (!has_features(r.status)) continue;
    found = i;
    EXPECT_NEAR(r.features.centroid.x, cx, 3);
    EXPECT_NEAR(r.features.area / (M_PI * 20 * 20), 1.0, 0.2);
  }
  EXPECT_GE(found, 1);
  EXPECT_LE(found, 6);
}

}  // namespace
}  // namespace projtrack
