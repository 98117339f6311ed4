// Our Canny must give exactly cv::Canny's edges (L1, 3×3): the estimators' results, the
// benchmark's numbers and the paper's comparison all assume OpenCV's detector.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "edges/canny.hpp"

namespace projtrack {
namespace {

cv::Mat ours(const cv::Mat& src, double low, double high, CannyDetector& detector) {
  const ImageView v = detector.detect(
      ImageView(src.data, src.cols, src.rows, static_cast<std::ptrdiff_t>(src.step)), low, high);
  return cv::Mat(v.height, v.width, CV_8UC1, const_cast<std::uint8_t*>(v.data),
                 static_cast<std::size_t>(v.stride))
      .clone();
}

cv::Mat opencv(const cv::Mat& src, double low, double high) {
  cv::Mat out;
  cv::Canny(src, out, low, high, 3, false);
  return out;
}

// Noise, flat discs with noise, and blurred versions: peaks, ties and plateaus of every kind.
cv::Mat random_image(cv::RNG& rng, int w, int h, int kind) {
  cv::Mat img(h, w, CV_8UC1);
  if (kind == 0) {
    rng.fill(img, cv::RNG::UNIFORM, 0, 256);
  } else {
    img.setTo(rng.uniform(0, 256));
    for (int i = 0; i < 3; ++i)
      cv::circle(img, {rng.uniform(0, w), rng.uniform(0, h)}, rng.uniform(1, 40),
                 cv::Scalar(rng.uniform(0, 256)), -1);
    cv::Mat noise(h, w, CV_8UC1);
    rng.fill(noise, cv::RNG::UNIFORM, 0, kind == 1 ? 2 : 24);
    img += noise;
    if (kind == 3) cv::blur(img, img, {3, 3});
  }
  return img;
}

TEST(Canny, SameEdgesAsOpenCVOnRandomImagesSizesAndThresholds) {
  cv::RNG rng(2026);
  CannyDetector detector;  // one detector for all: reused buffers must not leak state
  for (int i = 0; i < 400; ++i) {
    const int w = rng.uniform(1, 120), h = rng.uniform(1, 90);
    const cv::Mat img = random_image(rng, w, h, i % 4);
    const double low = rng.uniform(0.0, 300.0), high = rng.uniform(0.0, 600.0);
    const cv::Mat a = ours(img, low, high, detector), b = opencv(img, low, high);
    ASSERT_EQ(cv::countNonZero(a != b), 0)
        << w << "×" << h << " kind " << i % 4 << " low " << low << " high " << high;
  }
}

TEST(Canny, SameEdgesOnAPaddedView) {
  cv::RNG rng(7);
  const cv::Mat big = random_image(rng, 200, 150, 2);
  const cv::Mat view = big(cv::Rect(13, 9, 150, 120));  // stride > width
  CannyDetector detector;
  EXPECT_EQ(cv::countNonZero(ours(view, 40, 120, detector) != opencv(view.clone(), 40, 120)), 0);
}

TEST(Canny, ThresholdsBeyondEveryGradientGiveNoEdges) {
  cv::RNG rng(3);
  const cv::Mat img = random_image(rng, 64, 64, 0);
  CannyDetector detector;
  EXPECT_EQ(cv::countNonZero(ours(img, 1e9, 1e12, detector)), 0);
  EXPECT_EQ(cv::countNonZero(ours(img, 1e9, 1e12, detector) != opencv(img, 1e9, 1e12)), 0);
}

TEST(Canny, NaNThresholdsReadAsTheLowestLevel) {
  cv::RNG rng(9);
  const cv::Mat img = random_image(rng, 40, 30, 3);
  CannyDetector detector;
  const cv::Mat lowest = ours(img, -1, -1, detector);
  EXPECT_EQ(cv::countNonZero(ours(img, std::nan(""), std::nan(""), detector) != lowest), 0);
  EXPECT_EQ(cv::countNonZero(ours(img, -1e300, -5, detector) != lowest), 0);
}

TEST(Canny, AnInvalidSourceGivesAnEmptyView) {
  CannyDetector detector;
  EXPECT_TRUE(detector.detect(ImageView(), 10, 20).empty());
  const std::uint8_t pixels[4] = {0, 255, 0, 255};
  EXPECT_TRUE(detector.detect(ImageView(pixels, 2, 2, 1), 10, 20).empty());  // stride < width
}

}  // namespace
}  // namespace projtrack
