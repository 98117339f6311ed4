// The colours near each part of the object (LocalColours), and the flow model started from an
// outlined silhouette with them: an object whose two colours are each its surroundings' on the
// other side.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "segmentation/flow_segmenter.hpp"
#include "segmentation/local_colours.hpp"

namespace projtrack {
namespace {

const cv::Scalar kRed(40, 40, 200), kGreen(40, 200, 40);

// A frame whose left half is red and right half green, with a rectangle across the middle that is
// green on the left and red on the right (the object): over the frame, each colour is the
// object's as much as its surroundings'.
void crossed(cv::Mat& bgr, cv::Mat& inside) {
  bgr.create(40, 80, CV_8UC3);
  bgr(cv::Rect(0, 0, 40, 40)).setTo(kRed);
  bgr(cv::Rect(40, 0, 40, 40)).setTo(kGreen);
  bgr(cv::Rect(10, 10, 30, 20)).setTo(kGreen);
  bgr(cv::Rect(40, 10, 30, 20)).setTo(kRed);
  inside = cv::Mat::zeros(40, 80, CV_8U);
  inside(cv::Rect(10, 10, 60, 20)).setTo(255);
}

float evidence_at(LocalColours& local, const cv::Mat& bgr, cv::Point at, cv::Point2f moved,
                  double weight = 1) {
  cv::Mat odds = cv::Mat::zeros(bgr.size(), CV_32F);
  local.add_evidence(bgr, {0, 0, bgr.cols, bgr.rows}, moved, weight, odds);
  return odds.at<float>(at);
}

TEST(LocalColours, EachCellTellsTheColoursItSawApart) {
  cv::Mat bgr, inside;
  crossed(bgr, inside);
  cv::Mat around;
  cv::bitwise_not(inside, around);
  LocalColours local;
  local.learn(bgr, {0, 0, 80, 40}, inside, around, 2);
  ASSERT_TRUE(local.learned());
  // Green is the object on the left and the surroundings on the right; red the other way round.
  EXPECT_GT(evidence_at(local, bgr, {20, 20}, {}), 1);  // green, left
  EXPECT_LT(evidence_at(local, bgr, {5, 5}, {}), -1);   // red, left
  EXPECT_GT(evidence_at(local, bgr, {60, 20}, {}), 1);  // red, right
  EXPECT_LT(evidence_at(local, bgr, {75, 5}, {}), -1);  // green, right
  EXPECT_LE(std::abs(evidence_at(local, bgr, {20, 20}, {})), LocalColours::kMostNats);
  // The grid moves with the object: moved 40 px right, the right half reads the left cells.
  EXPECT_LT(evidence_at(local, bgr, {60, 20}, {40, 0}), -1);  // red, read by the left cell
  EXPECT_EQ(evidence_at(local, bgr, {20, 20}, {}, 0), 0);
  local.forget();
  EXPECT_EQ(evidence_at(local, bgr, {20, 20}, {}), 0);
}

TEST(LocalColours, AColourBothShareSaysNothingHoweverManyMorePixelsOneHas) {
  // One cell: 100 object pixels and 1 500 around them, all of one grey.
  cv::Mat bgr(40, 40, CV_8UC3, cv::Scalar(100, 100, 100));
  cv::Mat inside = cv::Mat::zeros(40, 40, CV_8U), around;
  inside(cv::Rect(15, 15, 10, 10)).setTo(255);
  cv::bitwise_not(inside, around);
  LocalColours local;
  local.learn(bgr, {0, 0, 40, 40}, inside, around, 1);
  EXPECT_NEAR(evidence_at(local, bgr, {20, 20}, {}), 0, 1e-4);
  // A colour neither saw: nothing either way.
  bgr.at<cv::Vec3b>(20, 20) = {0, 250, 0};
  EXPECT_EQ(evidence_at(local, bgr, {20, 20}, {}), 0);
}

// Frame t of a textured version of crossed(): the object moves down 1 px a frame along the line
// where the surroundings change colour; the camera is still.
void crossed_scene(int t, cv::Mat& bgr, cv::Mat& inside) {
  static const cv::Mat texture = [] {
    cv::Mat noise(400, 480, CV_8UC3);
    cv::RNG rng(3);
    rng.fill(noise, cv::RNG::UNIFORM, -20, 20);
    cv::GaussianBlur(noise, noise, {0, 0}, 1.2);
    return noise;
  }();
  bgr.create(240, 320, CV_8UC3);
  bgr(cv::Rect(0, 0, 160, 240)).setTo(kRed);
  bgr(cv::Rect(160, 0, 160, 240)).setTo(kGreen);
  cv::add(bgr, texture(cv::Rect(0, 0, 320, 240)), bgr);
  inside = cv::Mat::zeros(240, 320, CV_8U);
  const cv::Rect object(100, 60 + t, 120, 60);
  inside(object).setTo(255);
  cv::Mat own(240, 320, CV_8UC3);
  own(cv::Rect(0, 0, 160, 240)).setTo(kGreen);
  own(cv::Rect(160, 0, 160, 240)).setTo(kRed);
  cv::add(own, texture(cv::Rect(40, 150 - t, 320, 240)), own);  // its texture moves with it
  own.copyTo(bgr, inside);
}

double last_overlap(bool outlined) {
  cv::Mat bgr, truth, gray;
  FlowSegmenter segmenter;
  const FlowModelParams p;
  double overlap = 0;
  for (int t = 0; t <= 30; ++t) {
    crossed_scene(t, bgr, truth);
    WorkImages img;
    img.bgr = bgr.clone();
    cv::cvtColor(bgr, img.gray, cv::COLOR_BGR2GRAY);
    img.frame_width = bgr.cols;
    img.frame_height = bgr.rows;
    if (t == 0) {
      segmenter.start(img, truth, img, truth, p, outlined, false);
      continue;
    }
    if (!segmenter.follow(img, p)) return 0;
    const double both = cv::countNonZero(segmenter.silhouette() & truth);
    overlap = both / cv::countNonZero(segmenter.silhouette() | truth);
  }
  return overlap;
}

TEST(LocalColours, AnOutlinedSilhouetteIsFollowedWhereTheFrameWideColoursCannotTellIt) {
  const double with_local = last_overlap(true), without = last_overlap(false);
  RecordProperty("with", std::to_string(with_local));
  RecordProperty("without", std::to_string(without));
  EXPECT_GT(with_local, without + 0.05) << with_local << " against " << without;
}

}  // namespace
}  // namespace projtrack
