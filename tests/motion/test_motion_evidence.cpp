// The motion stage on generated pictures whose motion is known: a textured picture moved by a
// whole number of pixels, and a silhouette carried along a known flow.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "motion/dense_flow.hpp"
#include "motion/motion_evidence.hpp"

namespace projtrack {
namespace {

cv::Mat texture(cv::Size size, int seed) {
  cv::Mat noise(size, CV_8U);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, {0, 0}, 2.0);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  return noise;
}

cv::Mat shifted(const cv::Mat& m, int dx, int dy) {
  cv::Mat out;
  const cv::Mat move = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, dy);
  cv::warpAffine(m, out, move, m.size(), cv::INTER_NEAREST, cv::BORDER_REFLECT);
  return out;
}

TEST(DenseFlow, KnowsItsPresetsPatchSide) {
  // FlowSegmenter grows the region measured by a patch: the preset's own.
  EXPECT_EQ(cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST)->getPatchSize(),
            DenseFlow::kPatchSide);
}

TEST(DenseFlow, ReadsAWholePictureMoveAsTheMoveBack) {
  const cv::Mat first = texture({320, 240}, 1);
  DenseFlow flow;
  EXPECT_FALSE(flow.compute(first));  // nothing to compare with yet
  ASSERT_TRUE(flow.compute(shifted(first, 3, -2)));
  const cv::Scalar mean = cv::mean(flow.backward()(cv::Rect(40, 40, 240, 160)));
  EXPECT_NEAR(mean[0], -3, 0.5);  // each pixel came from 3 px to its left
  EXPECT_NEAR(mean[1], 2, 0.5);
  EXPECT_FALSE(flow.compute(texture({160, 120}, 2)));  // a new size: no flow
}

TEST(DenseFlow, EveryLevelReadsTheMoveAndALevelMayChangeBetweenFrames) {
  const cv::Mat first = texture({320, 240}, 1);
  DenseFlow flow;
  flow.compute(first, 2);
  int dx = 0;
  for (const int level : {2, 1, 0, 2, 0, 1}) {
    dx += 2;
    ASSERT_TRUE(flow.compute(shifted(first, dx, 0), level)) << level;
    const cv::Scalar mean = cv::mean(flow.backward()(cv::Rect(40, 40, 240, 160)));
    EXPECT_NEAR(mean[0], -2, 0.5) << level;
    EXPECT_NEAR(mean[1], 0, 0.5) << level;
  }
}

TEST(DenseFlow, OnlyTheRegionAskedForIsMeasured) {
  // A region that moves about and changes its size from frame to frame (a new DIS for each new
  // size), at every level, near the frame's edges and too small for DIS: the move read within
  // it, zero outside.
  const cv::Mat first = texture({320, 240}, 1);
  DenseFlow flow;
  flow.compute(first, 2);
  int dx = 0;
  const cv::Rect regions[] = {{100, 80, 120, 90}, {0, 0, 90, 70},     {250, 170, 70, 70},
                              {140, 100, 8, 6},   {60, 40, 200, 150}, {100, 80, 120, 90}};
  int level = 0;
  for (const cv::Rect& region : regions) {
    dx += 2;
    level = (level + 1) % 3;
    ASSERT_TRUE(flow.compute(shifted(first, dx, 0), level, region)) << region;
    const cv::Mat& f = flow.backward();
    ASSERT_EQ(f.size(), first.size());
    // Within the region, away from the frame's border (reflected there) and the region's edge.
    const cv::Rect inner =
        cv::Rect(region.x + 6, region.y + 6, region.width - 12, region.height - 12) &
        cv::Rect(8, 8, 304, 224);
    if (!inner.empty()) {
      const cv::Scalar mean = cv::mean(f(inner));
      EXPECT_NEAR(mean[0], -2, 0.5) << region << " level " << level;
      EXPECT_NEAR(mean[1], 0, 0.5) << region << " level " << level;
    }
    // Far outside it, nothing was measured.
    cv::Mat outside(f.size(), CV_8U, cv::Scalar(255));
    outside(cv::Rect(region.x - 40, region.y - 40, region.width + 80, region.height + 80) &
            cv::Rect({0, 0}, f.size()))
        .setTo(0);
    std::vector<cv::Mat> parts;
    cv::split(f, parts);
    EXPECT_EQ(cv::countNonZero((parts[0] != 0) & outside), 0) << region;
  }
}

TEST(DenseFlow, TinyFramesAndNewSizesGiveNoFlowAndNoException) {
  DenseFlow flow;
  const cv::Mat tiny = texture({12, 10}, 3);
  EXPECT_FALSE(flow.compute(tiny));
  EXPECT_FALSE(flow.compute(tiny));  // DIS refuses frames this small: no flow, nothing thrown
  // Too small to halve, large enough to read whole; then one that is halved, odd-sized.
  for (const cv::Size size : {cv::Size(28, 20), cv::Size(65, 33)}) {
    const cv::Mat a = texture(size, 5);
    flow.compute(a);
    ASSERT_TRUE(flow.compute(shifted(a, 1, 0))) << size;
    EXPECT_EQ(flow.backward().size(), size);
    EXPECT_EQ(flow.backward().type(), CV_32FC2);
  }
  flow.reset();
  // Sizes that change back and forth, with a reset between (a new track): each comparable pair
  // gives a flow (a reused DIS once crashed here).
  for (const cv::Size size : {cv::Size(320, 240), cv::Size(160, 120), cv::Size(320, 240)}) {
    const cv::Mat a = texture(size, 4);
    flow.compute(a);
    for (int i = 1; i <= 3; ++i) EXPECT_TRUE(flow.compute(shifted(a, i, 0)));
    flow.reset();
  }
}

TEST(LargestComponent, IsTheFlowsInfinityNorm) {
  // Widths that leave a part vector at each row's end; the largest anywhere, either sign.
  cv::RNG rng(7);
  for (const int width : {1, 5, 33, 427}) {
    cv::Mat flow(9, width, CV_32FC2);
    rng.fill(flow, cv::RNG::UNIFORM, -20, 20);
    EXPECT_FLOAT_EQ(largest_component(flow), static_cast<float>(cv::norm(flow, cv::NORM_INF)))
        << width;
    flow.at<cv::Point2f>(8, width - 1).y = -75.5f;
    EXPECT_FLOAT_EQ(largest_component(flow), 75.5f) << width;
  }
  EXPECT_EQ(largest_component(cv::Mat::zeros(4, 4, CV_32FC2)), 0.f);
}

TEST(CarryAlongFlow, MovesTheSilhouetteWhereItsPixelsWent) {
  cv::Mat last = cv::Mat::zeros(100, 100, CV_32F);
  last(cv::Rect(20, 30, 10, 10)).setTo(1);
  const cv::Mat flow(100, 100, CV_32FC2, cv::Scalar(-5, -4));  // came from 5 left, 4 up
  cv::Mat map, prior;
  const cv::Rect written =
      carry_along_flow(last, {20, 30, 10, 10}, flow, {0, 0, 100, 100}, map, prior);
  EXPECT_FLOAT_EQ(cv::sum(prior)[0], 100);
  EXPECT_FLOAT_EQ(prior.at<float>(34, 25), 1);
  EXPECT_FLOAT_EQ(prior.at<float>(30, 20), 0);
  EXPECT_FLOAT_EQ(cv::sum(prior(written))[0], 100);  // all that was carried lies in the box
}

TEST(CarryAlongFlow, GivesWhatAWholeFrameRemapGives) {
  // Only the box the last silhouette can reach is remapped: the prior must be the whole frame's.
  cv::Mat last = cv::Mat::zeros(120, 160, CV_32F);
  cv::ellipse(last, {60, 50}, {25, 15}, 30, 0, 360, cv::Scalar(1), cv::FILLED);
  cv::Mat flow(120, 160, CV_32FC2);
  cv::RNG rng(7);
  rng.fill(flow, cv::RNG::UNIFORM, -9, 9);
  cv::GaussianBlur(flow, flow, {0, 0}, 3.0);
  cv::Mat whole_map(flow.size(), CV_32FC2), whole;
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x)
      whole_map.at<cv::Point2f>(y, x) = cv::Point2f(x, y) + flow.at<cv::Point2f>(y, x);
  cv::remap(last, whole, whole_map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
  cv::Mat map, prior;
  const cv::Rect held = cv::boundingRect(last > 0), frame(0, 0, 160, 120);
  carry_along_flow(last, held, flow, frame, map, prior);
  EXPECT_GT(cv::sum(prior)[0], 100);
  EXPECT_EQ(cv::norm(prior, whole, cv::NORM_INF), 0);
  // A flow measured in part of the frame (zero elsewhere): the same as the whole frame's.
  const cv::Rect moving(30, 20, 70, 60);
  cv::Mat part = cv::Mat::zeros(flow.size(), CV_32FC2);
  flow(moving).copyTo(part(moving));
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x)
      whole_map.at<cv::Point2f>(y, x) = cv::Point2f(x, y) + part.at<cv::Point2f>(y, x);
  cv::remap(last, whole, whole_map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
  prior = cv::Mat::zeros(flow.size(), CV_32F);
  carry_along_flow(last, held, part, moving, map, prior);
  EXPECT_EQ(cv::norm(prior, whole, cv::NORM_INF), 0);
  // Nothing to carry: a prior of another size is made anew, all zero.
  prior = cv::Mat::ones(10, 10, CV_32F);
  EXPECT_TRUE(
      carry_along_flow(cv::Mat::zeros(120, 160, CV_32F), cv::Rect(), flow, frame, map, prior)
          .empty());
  EXPECT_EQ(prior.size(), flow.size());
  EXPECT_EQ(cv::countNonZero(prior), 0);
}

TEST(SplitMotion, ReadsTheRingAsADilationWouldAtTheFrameEdge) {
  // An object at the frame's corner: its ring is cut by the frame, not wrapped or mirrored.
  cv::Mat flow(50, 50, CV_32FC2, cv::Scalar(2, 0));
  flow(cv::Rect(0, 0, 10, 10)).setTo(cv::Scalar(-3, 1));
  cv::Mat inside = cv::Mat::zeros(50, 50, CV_8U);
  inside(cv::Rect(0, 0, 10, 10)).setTo(255);
  cv::Mat count, around;
  std::vector<float> samples;
  const MotionSplit split = split_motion(flow, inside, 0.5, count, around, samples);
  ASSERT_TRUE(split.valid);
  EXPECT_FLOAT_EQ(split.object.x, -3);
  EXPECT_FLOAT_EQ(split.surroundings.x, 2);
  EXPECT_FLOAT_EQ(split.separation, std::hypot(5.0f, 1.0f));
}

TEST(MotionEvidence, FavoursPixelsThatMoveWithTheObject) {
  cv::Mat flow(60, 60, CV_32FC2, cv::Scalar(1, 0));         // the surroundings
  flow(cv::Rect(20, 20, 20, 20)).setTo(cv::Scalar(-4, 3));  // the object
  cv::Mat inside = cv::Mat::zeros(60, 60, CV_8U);
  inside(cv::Rect(22, 22, 16, 16)).setTo(255);
  cv::Mat count, around;
  std::vector<float> samples;
  const MotionSplit split = split_motion(flow, inside, 0.5, count, around, samples);
  ASSERT_TRUE(split.valid);
  EXPECT_NEAR(split.object.x, -4, 1e-6);
  EXPECT_NEAR(split.surroundings.x, 1, 1e-6);
  cv::Mat log_odds = cv::Mat::zeros(60, 60, CV_32F);
  add_motion_evidence(flow, split, 2.0, 1.0, log_odds);
  EXPECT_FLOAT_EQ(log_odds.at<float>(21, 21), 2.0f);  // the object's edge, outside `inside`
  EXPECT_FLOAT_EQ(log_odds.at<float>(5, 5), -2.0f);
  // Motions closer than min_separation tell nothing apart.
  cv::Mat none = cv::Mat::zeros(60, 60, CV_32F);
  add_motion_evidence(flow, split, 2.0, 10.0, none);
  EXPECT_EQ(cv::countNonZero(none), 0);
}

}  // namespace
}  // namespace projtrack
