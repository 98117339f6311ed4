// What the flow model's starts share: a GrabCut that gives the same cut whatever ran before it,
// and the choice among cuts at several sizes of the one the others agree with.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "segmentation/grab_cut.hpp"
#include "segmentation/point_start.hpp"

namespace projtrack {
namespace {

// Uniform noise in [back_lo, back_hi) of `type`, and in [shape_lo, shape_hi) where `shape` (CV_8U)
// is set.
cv::Mat noise_with_shape(const cv::Mat& shape, int type, int seed, int back_lo, int back_hi,
                         int shape_lo, int shape_hi) {
  cv::Mat out(shape.size(), type), inside(shape.size(), type);
  cv::RNG rng(seed);
  rng.fill(out, cv::RNG::UNIFORM, back_lo, back_hi);
  rng.fill(inside, cv::RNG::UNIFORM, shape_lo, shape_hi);
  inside.copyTo(out, shape);
  return out;
}

// A noisy frame with a noisy disc of other colours. (GrabCut's mixtures' k-means starts from
// random centres, but a scene this plain is cut the same from any; on davis-dev's libby the box's
// cut varied with the generator's state.)
cv::Mat noisy_disc() {
  cv::Mat where = cv::Mat::zeros(120, 160, CV_8U);
  cv::circle(where, {80, 60}, 30, 255, cv::FILLED);
  return noise_with_shape(where, CV_8UC3, 3, 40, 140, 100, 220);
}

TEST(GrabCut, TheSameCutWhateverRanBefore) {
  const cv::Mat bgr = noisy_disc();
  const cv::Rect box(45, 25, 70, 70);
  cv::Mat first, second;
  cv::theRNG() = cv::RNG(1);
  ASSERT_TRUE(grab_cut(bgr, first, box, 3));
  cv::theRNG() = cv::RNG(12345);  // another state of the thread's generator
  const std::uint64_t state = cv::theRNG().state;
  ASSERT_TRUE(grab_cut(bgr, second, box, 3));
  EXPECT_EQ(cv::countNonZero(first != second), 0);
  EXPECT_EQ(cv::theRNG().state, state);  // the thread's generator is given back untouched
}

cv::Mat square(int x, int side) {
  cv::Mat m = cv::Mat::zeros(100, 100, CV_8U);
  m(cv::Rect(x, 20, side, side)).setTo(255);
  return m;
}

TEST(MostAgreed, TheCandidateTheOthersOverlapMost) {
  // Two cuts of nearly one object and one elsewhere: one of the two; the empty one takes no part.
  EXPECT_EQ(most_agreed({square(60, 30), square(10, 30), cv::Mat(), square(12, 30)}), 3);
  EXPECT_EQ(most_agreed({square(10, 30), square(60, 30), square(12, 30)}), 2);
  // A tie goes to the later (larger) candidate; nothing to choose from: -1.
  EXPECT_EQ(most_agreed({square(10, 30), square(10, 30)}), 1);
  EXPECT_EQ(most_agreed({square(10, 30)}), 0);
  EXPECT_EQ(most_agreed({cv::Mat(), cv::Mat()}), -1);
}

// A small gray frame nearly filled by one bright ellipse (the real set's disc at half size).
WorkImages small_bright_ellipse() {
  cv::Mat where = cv::Mat::zeros(128, 183, CV_8U);
  cv::ellipse(where, {105, 70}, {92, 48}, -20, 0, 360, 255, cv::FILLED);
  WorkImages img;
  img.gray = noise_with_shape(where, CV_8U, 5, 35, 45, 225, 235);
  cv::cvtColor(img.gray, img.bgr, cv::COLOR_GRAY2BGR);
  return img;
}

TEST(ObjectsAtPoint, ACutOfLittleMoreThanItsCertainDiscHasCollapsed) {
  // Inside the ellipse, its outline within reach: the smallest square's cut can keep just the
  // certain disc, which is over 2 % of that square on a frame this small.
  const WorkImages img = small_bright_ellipse();
  const cv::Point p(87, 50);
  const std::vector<cv::Mat> found = objects_at_point(img, p, {12, 25, 38, 51});
  ASSERT_EQ(found.size(), 4U);
  for (const cv::Mat& m : found) {
    if (m.empty()) continue;
    EXPECT_EQ(m.at<std::uint8_t>(p), 255);
    EXPECT_GT(cv::countNonZero(m), 2 * 13);  // the certain disc of radius 2 holds 13 pixels
  }
}

}  // namespace
}  // namespace projtrack
