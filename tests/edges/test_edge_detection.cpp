// Edge detection: Canny, Sobel and "input" into a reusable edge map.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "projtrack/edge_detection.hpp"
#include "projtrack/estimator.hpp"

namespace projtrack {
namespace {

ImageView view_of(const cv::Mat& m) { return ImageView(m.data, m.cols, m.rows, m.step); }

// A grey disc (radius 50, value 200) on a darker background (60), lightly noisy.
cv::Mat grey_disc(int w = 320, int h = 240) {
  cv::Mat img(h, w, CV_8U, cv::Scalar(60));
  cv::circle(img, {w / 2, h / 2}, 50, cv::Scalar(200), cv::FILLED, cv::LINE_AA);
  cv::Mat noise(h, w, CV_8U);
  cv::theRNG().state = 7;
  cv::randn(noise, 0, 4);
  img += noise;
  return img;
}

int count_edges(const ImageView& e) {
  int n = 0;
  for (int y = 0; y < e.height; ++y)
    for (int x = 0; x < e.width; ++x) n += e.at(x, y) != 0;
  return n;
}

TEST(EdgeMap, InputIsReadInPlace) {
  const cv::Mat img = grey_disc();
  EdgeMap map;
  EdgeParams p;
  p.detector = EdgeDetector::Input;
  const ImageView e = map.detect(view_of(img), p);
  EXPECT_EQ(e.data, img.data);
  EXPECT_EQ(e.stride, static_cast<std::ptrdiff_t>(img.step));
}

TEST(EdgeMap, InputAboveABlackLevel) {
  // Limited-range video stores black as 16: an edge map there has 16 for "no edge".
  cv::Mat img(20, 30, CV_8U, cv::Scalar(16));
  img(cv::Rect(5, 5, 10, 1)).setTo(235);
  EdgeMap map;
  EdgeParams p;
  p.detector = EdgeDetector::Input;
  p.input_black_level = 16;
  const ImageView e = map.detect(view_of(img), p);
  EXPECT_NE(e.data, img.data);
  EXPECT_EQ(count_edges(e), 10);
  p.input_black_level = 0;
  EXPECT_EQ(count_edges(map.detect(view_of(img), p)), 30 * 20);
}

TEST(EdgeMap, CannyAndSobelCloseTheContourOfADisc) {
  const cv::Mat img = grey_disc();
  const double disc_area = 3.14159265 * 50 * 50;
  for (EdgeDetector d : {EdgeDetector::Canny, EdgeDetector::Sobel}) {
    EdgeMap map;
    EdgeParams p;
    p.detector = d;
    const ImageView e = map.detect(view_of(img), p);
    ASSERT_EQ(e.width, img.cols);
    const Features f = make_estimator(Method::PixelFilling)->estimate(e, {160, 120}, {});
    ASSERT_EQ(f.status, EstimateStatus::Ok);
    EXPECT_NEAR(f.centroid.x, 160, 0.5);
    EXPECT_NEAR(f.centroid.y, 120, 0.5);
    // Canny's thin line sits on the boundary; Sobel's band is a few pixels thick.
    EXPECT_LE(f.area, disc_area * 1.02);
    EXPECT_GE(f.area, disc_area * (d == EdgeDetector::Canny ? 0.93 : 0.80));
  }
}

TEST(EdgeMap, PaddedRowsGiveTheSameEdges) {
  const cv::Mat img = grey_disc(101, 77);
  cv::Mat wide(77, 128, CV_8U, cv::Scalar(255));
  img.copyTo(wide(cv::Rect(0, 0, 101, 77)));
  const cv::Mat padded = wide(cv::Rect(0, 0, 101, 77));
  for (EdgeDetector d : {EdgeDetector::Canny, EdgeDetector::Sobel}) {
    EdgeMap a, b;
    EdgeParams p;
    p.detector = d;
    const ImageView ea = a.detect(view_of(img), p);
    const ImageView eb = b.detect(view_of(padded), p);
    ASSERT_EQ(eb.width, 101);
    for (int y = 0; y < 77; ++y)
      for (int x = 0; x < 101; ++x) ASSERT_EQ(ea.at(x, y), eb.at(x, y)) << x << ", " << y;
  }
}

TEST(EdgeMap, ReusesItsBuffersFromFrameToFrame) {
  const cv::Mat img = grey_disc();
  for (EdgeDetector d : {EdgeDetector::Canny, EdgeDetector::Sobel}) {
    EdgeMap map;
    EdgeParams p;
    p.detector = d;
    const std::uint8_t* first = map.detect(view_of(img), p).data;
    EXPECT_EQ(map.detect(view_of(img), p).data, first);
  }
}

TEST(EdgeMap, ARegionHasTheWholeFramesEdgesAwayFromItsBorder) {
  const cv::Mat img = grey_disc();
  for (EdgeDetector d : {EdgeDetector::Canny, EdgeDetector::Sobel}) {
    EdgeMap whole_map, region_map;
    EdgeParams p;
    p.detector = d;
    const ImageView whole = whole_map.detect(view_of(img), p);
    const Rect r{90, 50, 140, 130};
    const ImageView part = region_map.detect(view_of(img), p, r);
    ASSERT_EQ(part.width, r.width);
    ASSERT_EQ(part.height, r.height);
    for (int y = 4; y < r.height - 4; ++y)
      for (int x = 4; x < r.width - 4; ++x)
        ASSERT_EQ(part.at(x, y), whole.at(r.x + x, r.y + y)) << x << ", " << y;
    // Smaller regions reuse the same buffers; regions are clipped to the frame.
    // (Canny's map starts past a border row as long as the region's row: the same buffer, an
    // address that moves by at most that row.)
    const std::uint8_t* buffer = part.data;
    const std::uint8_t* smaller = region_map.detect(view_of(img), p, {100, 60, 50, 40}).data;
    EXPECT_LE(std::abs(smaller - buffer), part.stride + 1);
    EXPECT_EQ(region_map.detect(view_of(img), p, {300, 200, 100, 100}).width, 20);
    EXPECT_TRUE(region_map.detect(view_of(img), p, {400, 10, 5, 5}).empty());
  }
}

TEST(EdgeMap, BlurRemovesNoiseEdges) {
  cv::Mat noise(120, 160, CV_8U);
  cv::theRNG().state = 3;
  cv::randn(noise, 128, 20);
  EdgeMap map;
  EdgeParams p;
  p.blur = 0;
  const int sharp = count_edges(map.detect(view_of(noise), p));
  p.blur = 3;
  const int smooth = count_edges(map.detect(view_of(noise), p));
  EXPECT_LT(smooth * 2, sharp);
}

TEST(EdgeMap, CannyThresholdsMaySwap) {
  const cv::Mat img = grey_disc();
  EdgeMap a, b;
  EdgeParams p;
  p.low = 40;
  p.high = 120;
  const ImageView ea = a.detect(view_of(img), p);
  std::swap(p.low, p.high);
  const ImageView eb = b.detect(view_of(img), p);
  EXPECT_EQ(count_edges(ea), count_edges(eb));
}

TEST(EdgeMap, TinyEmptyAndInvalidImages) {
  EdgeMap map;
  for (EdgeDetector d : {EdgeDetector::Canny, EdgeDetector::Sobel, EdgeDetector::Input}) {
    EdgeParams p;
    p.detector = d;
    EXPECT_TRUE(map.detect(ImageView(), p).empty());
    const std::uint8_t px[6] = {10, 200, 30, 40, 50, 60};
    EXPECT_TRUE(map.detect(ImageView(px, 3, 2, 2), p).empty());  // stride < width
    for (auto [w, h] : {std::pair{1, 1}, std::pair{2, 2}, std::pair{3, 2}, std::pair{1, 6}}) {
      const ImageView e = map.detect(ImageView(px, w, h, w), p);
      EXPECT_EQ(e.width, w);
      EXPECT_EQ(e.height, h);
    }
  }
}

TEST(EdgeMap, OutOfRangeParametersAreClamped) {
  const cv::Mat img = grey_disc();
  EdgeMap map;
  EdgeParams p;
  p.blur = -5;
  p.low = -10;
  p.high = -1;
  const ImageView e = map.detect(view_of(img), p);
  EXPECT_EQ(e.width, img.cols);
  p.blur = 1000;
  EXPECT_EQ(map.detect(view_of(img), p).width, img.cols);
}

TEST(EdgeParamsValidation, CannyThresholdsOutOfOrderAndNaNAreReported) {
  EdgeParams p;
  EXPECT_EQ(validate(p), "");
  p.low = 200;
  p.high = 100;
  EXPECT_NE(validate(p).find("edge-threshold-low 200 is above edge-threshold-high 100"),
            std::string::npos);
  p.detector = EdgeDetector::Sobel;  // Sobel reads `low` only
  EXPECT_EQ(validate(p), "");
  p.low = std::nan("");
  EXPECT_NE(validate(p), "");
}

}  // namespace
}  // namespace projtrack
