// The flow model's frame reads the same colours from every chroma layout the element passes:
// planar (I420), pairs (NV12) and macro-pixels (YUY2), and its luma alone from a gray frame.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace projtrack
