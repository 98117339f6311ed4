// Tracker::silhouette: the flow model's mask out at full resolution, the same pixels the
// estimate measured; nothing for the edges model, before a frame or into an unusable buffer.
#include <gtest/gtest.h>

#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "projtrack/tracker.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

constexpr int kW = 320, kH = 240;

// A dark blue disc of radius 40 at (cx, 120) on a light wall, as I420.
cv::Mat disc_i420(int cx) {
  cv::Mat bgr(kH, kW, CV_8UC3, cv::Scalar(205, 210, 215)), i420;
  cv::circle(bgr, {cx, 120}, 40, cv::Scalar(120, 40, 20), cv::FILLED);
  cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  return i420;
}

TrackerParams manual(ObjectModelKind model) {
  TrackerParams tp;
  tp.model = model;
  tp.acquisition = Acquisition::Manual;
  return tp;
}

// The mask in a buffer with 16 padding bytes a row, set to 7 so that a write there shows.
struct Padded {
  static constexpr int kStride = kW + 16;
  std::vector<std::uint8_t> bytes = std::vector<std::uint8_t>(kStride * kH, 7);
  double area() const {
    double n = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) n += bytes[y * kStride + x] == 255;
    return n;
  }
  std::uint8_t at(int x, int y) const { return bytes[y * kStride + x]; }
  bool padding_untouched() const {
    for (int y = 0; y < kH; ++y)
      for (int x = kW; x < kStride; ++x)
        if (bytes[y * kStride + x] != 7) return false;
    return true;
  }
};

TEST(TrackerSilhouette, TheMaskIsTheMeasuredObject) {
  Tracker t;
  t.seed({150, 120});
  for (int i = 0; i < 5; ++i) {
    const cv::Mat f = disc_i420(150 + 4 * i);
    const TrackResult r = t.track(test::i420_view(f, kW, kH), EdgeParams{}, i / 30.0,
                                  Method::PixelFilling, {}, manual(ObjectModelKind::Flow));
    ASSERT_TRUE(has_features(r.status)) << status_name(r.status) << ": " << r.detail;
    Padded m;
    ASSERT_TRUE(t.silhouette(m.bytes.data(), kW, kH, Padded::kStride));
    // Pixel filling measures the silhouette's own pixels: the same count.
    EXPECT_NEAR(m.area(), r.features.area, 0.01 * r.features.area) << "frame " << i;
    EXPECT_EQ(m.at(150 + 4 * i, 120), 255);
    EXPECT_EQ(m.at(10, 10), 0);
    EXPECT_EQ(m.at(150 + 4 * i + 50, 120), 0);
    EXPECT_TRUE(m.padding_untouched());
  }
}

TEST(TrackerSilhouette, NoneBeforeAFrameWithTheEdgesModelOrIntoABadBuffer) {
  Tracker t;
  Padded m;
  EXPECT_FALSE(t.silhouette(m.bytes.data(), kW, kH, Padded::kStride));
  EXPECT_EQ(m.area(), 0);  // cleared all the same
  EXPECT_EQ(m.at(5, 5), 0);

  const cv::Mat f = disc_i420(160);
  t.seed({160, 120});
  ASSERT_TRUE(has_features(t.track(test::i420_view(f, kW, kH), EdgeParams{}, 0, Method::GridFilling,
                                   {}, manual(ObjectModelKind::Flow))
                               .status));
  EXPECT_FALSE(t.silhouette(nullptr, kW, kH, kW));
  EXPECT_FALSE(t.silhouette(m.bytes.data(), kW, kH, kW - 1));
  EXPECT_FALSE(t.silhouette(m.bytes.data(), 0, kH, kW));
  // A mask smaller than the frame: the silhouette's part within it.
  ASSERT_TRUE(t.silhouette(m.bytes.data(), kW, kH, Padded::kStride));
  std::vector<std::uint8_t> corner(140 * 140, 7);
  ASSERT_TRUE(t.silhouette(corner.data(), 140, 140, 140));
  for (int y = 0; y < 140; ++y)
    for (int x = 0; x < 140; ++x) ASSERT_EQ(corner[y * 140 + x], m.at(x, y)) << x << "," << y;

  Tracker edges;
  edges.seed({160, 120});
  ASSERT_TRUE(has_features(edges
                               .track(test::i420_view(f, kW, kH), EdgeParams{}, 0,
                                      Method::GridFilling, {}, manual(ObjectModelKind::Edges))
                               .status));
  EXPECT_FALSE(edges.silhouette(m.bytes.data(), kW, kH, Padded::kStride));
  EXPECT_EQ(m.area(), 0);
}

TEST(TrackerSilhouette, EveryFramePixelOfACoarseWorkPixelIsDrawnAsItIs) {
  // The flow model at 4 frame px a work pixel, on a frame whose width is no multiple of 4, the
  // disc cut by its right edge: the drawn mask is SilhouetteMask::contains() pixel for pixel.
  constexpr int kWide = 330;
  cv::Mat bgr(kH, kWide, CV_8UC3, cv::Scalar(205, 210, 215)), i420,
      seed = cv::Mat::zeros(kH, kWide, CV_8U);
  cv::circle(bgr, {310, 120}, 40, cv::Scalar(120, 40, 20), cv::FILLED);
  cv::circle(seed, {310, 120}, 40, 255, cv::FILLED);
  cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  TrackerParams tp = manual(ObjectModelKind::Flow);
  // The disc cut by the edge (about 4 200 px) at a sixteenth of its pixels: scale 4.
  tp.flow.object_pixels = 4200 / 16.0;
  Tracker t;
  ASSERT_TRUE(t.seed_mask(ImageView(seed.data, kWide, kH, kWide)));
  for (int i = 0; i < 3; ++i) {
    const TrackResult r = t.track(test::i420_view(i420, kWide, kH), EdgeParams{}, i / 30.0,
                                  Method::PixelFilling, {}, tp);
    ASSERT_TRUE(has_features(r.status)) << status_name(r.status) << ": " << r.detail;
    const SilhouetteMask s = t.silhouette();
    ASSERT_EQ(s.scale, 4);
    constexpr int kStride = kWide + 16;
    std::vector<std::uint8_t> drawn(kStride * kH, 7);
    ASSERT_TRUE(t.silhouette(drawn.data(), kWide, kH, kStride));
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kWide; ++x)
        ASSERT_EQ(drawn[y * kStride + x], s.contains({x, y}) ? 255 : 0) << x << "," << y;
      for (int x = kWide; x < kStride; ++x) ASSERT_EQ(drawn[y * kStride + x], 7);
    }
    EXPECT_EQ(drawn[120 * kStride + kWide - 1], 255);  // the disc reaches the right edge
  }
}

TEST(TrackerSilhouette, ResetForgetsIt) {
  Tracker t;
  const cv::Mat f = disc_i420(160);
  t.seed({160, 120});
  t.track(test::i420_view(f, kW, kH), EdgeParams{}, 0, Method::GridFilling, {},
          manual(ObjectModelKind::Flow));
  Padded m;
  ASSERT_TRUE(t.silhouette(m.bytes.data(), kW, kH, Padded::kStride));
  t.reset();
  EXPECT_FALSE(t.silhouette(m.bytes.data(), kW, kH, Padded::kStride));
}

}  // namespace
}  // namespace projtrack
