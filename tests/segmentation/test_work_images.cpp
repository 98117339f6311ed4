// The flow model's frame reads the same colours from every chroma layout the element passes:
// planar (I420), pairs (NV12) and macro-pixels (YUY2), and its luma alone from a gray frame.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "segmentation/work_images.hpp"

namespace projtrack {
namespace {

constexpr int kW = 96, kH = 64;

// A picture of smooth colour ramps and a few sharp patches, as I420 planes (OpenCV's layout).
cv::Mat picture_i420() {
  cv::Mat bgr(kH, kW, CV_8UC3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(x * 2, y * 3, 255 - x - y);
  cv::rectangle(bgr, {10, 10, 20, 14}, cv::Scalar(20, 200, 40), cv::FILLED);
  cv::rectangle(bgr, {50, 30, 30, 20}, cv::Scalar(220, 30, 180), cv::FILLED);
  cv::Mat i420;
  cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  return i420;
}

ColorView i420_view(const cv::Mat& i420) {
  const std::uint8_t* y = i420.data;
  const std::uint8_t* u = y + kW * kH;
  const std::uint8_t* v = u + (kW / 2) * (kH / 2);
  return {ImageView(y, kW, kH, kW), ChromaView{u, v, kW / 2, 1, 1, 1}, {}};
}

WorkImages read(const ColorView& frame, int scale) {
  WorkImages img;
  build_work_images(frame, scale, img);
  return img;
}

void expect_same(const WorkImages& a, const WorkImages& b, double tolerance) {
  ASSERT_EQ(a.bgr.size(), b.bgr.size());
  double largest = 0;
  cv::minMaxLoc(cv::abs(a.bgr.reshape(1) - b.bgr.reshape(1)), nullptr, &largest);
  EXPECT_LE(largest, tolerance);
  EXPECT_EQ(cv::norm(a.gray, b.gray, cv::NORM_INF), 0);
}

TEST(WorkImages, EveryChromaLayoutReadsTheSameColours) {
  const cv::Mat i420 = picture_i420();
  const ColorView planar = i420_view(i420);
  // NV12: the same samples as U, V pairs.
  std::vector<std::uint8_t> uv(kW * kH / 2);
  for (int y = 0; y < kH / 2; ++y)
    for (int x = 0; x < kW / 2; ++x) {
      uv[y * kW + 2 * x] = planar.chroma.u[y * (kW / 2) + x];
      uv[y * kW + 2 * x + 1] = planar.chroma.v[y * (kW / 2) + x];
    }
  const ColorView nv12{planar.luma, ChromaView{uv.data(), uv.data() + 1, kW, 2, 1, 1}, {}};
  // YUY2: Y0 U Y1 V per two pixels, a chroma row per luma row (each 4:2:0 row twice).
  std::vector<std::uint8_t> yuy2(2 * kW * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW / 2; ++x) {
      std::uint8_t* m = &yuy2[y * 2 * kW + 4 * x];
      m[0] = planar.luma.at(2 * x, y);
      m[1] = planar.chroma.u[(y / 2) * (kW / 2) + x];
      m[2] = planar.luma.at(2 * x + 1, y);
      m[3] = planar.chroma.v[(y / 2) * (kW / 2) + x];
    }
  const ColorView packed{planar.luma, ChromaView{&yuy2[1], &yuy2[3], 2 * kW, 4, 1, 0}, {}};
  for (int scale : {1, 2, 3}) {
    const WorkImages reference = read(planar, scale);
    expect_same(reference, read(nv12, scale), 0);
    // Resampled from twice the rows, then widened from video range to full (by 255/224).
    expect_same(reference, read(packed, scale), 3);
  }
}

TEST(WorkImages, AGrayFrameIsItsLumaInEveryChannel) {
  const cv::Mat i420 = picture_i420();
  const ColorView colour = i420_view(i420);
  const WorkImages gray = read(ColorView{colour.luma, {}, {}}, 2);
  EXPECT_EQ(gray.size(), cv::Size(kW / 2, kH / 2));
  cv::Mat channels[3];
  cv::split(gray.bgr, channels);
  for (const cv::Mat& c : channels) EXPECT_EQ(cv::norm(c, gray.gray, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(gray.gray, read(colour, 2).gray, cv::NORM_INF), 0);
}

// Video range read as full range: luma 16-235 and chroma 16-240 widened to 0-255 (chroma about
// 128), then OpenCV's YCrCb to BGR; Cr and Cb each by their own value.
TEST(WorkImages, VideoRangeIsReadAsFullRange) {
  struct Colour {
    std::uint8_t y, u, v;
  };
  for (const Colour c : {Colour{16, 128, 128}, Colour{235, 128, 128}, Colour{81, 90, 240},
                         Colour{145, 54, 34}, Colour{41, 240, 110}}) {
    std::vector<std::uint8_t> luma(kW * kH, c.y), u(kW * kH / 4, c.u), v(kW * kH / 4, c.v);
    const ColorView frame{
        ImageView(luma.data(), kW, kH, kW), ChromaView{u.data(), v.data(), kW / 2, 1, 1, 1}, {}};
    const auto full = [](double value, double low, double span) {
      return cv::saturate_cast<std::uint8_t>(std::lround((value - low) * 255.0 / span));
    };
    const std::uint8_t y = full(c.y, 16, 219);
    const auto chroma = [](double value) {
      return cv::saturate_cast<std::uint8_t>(std::lround(128 + (value - 128) * 255.0 / 224.0));
    };
    cv::Mat expected;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar(y, chroma(c.v), chroma(c.u))), expected,
                 cv::COLOR_YCrCb2BGR);
    const WorkImages img = read(frame, 2);
    EXPECT_EQ(img.gray.at<std::uint8_t>(5, 7), y);
    EXPECT_EQ(img.bgr.at<cv::Vec3b>(5, 7), expected.at<cv::Vec3b>(0, 0))
        << int(c.y) << " " << int(c.u) << " " << int(c.v);
  }
}

}  // namespace
}  // namespace projtrack
