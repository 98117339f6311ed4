// The tracker's API for what changes under it between frames (Tracker::rescale, relearn) and for
// its silhouette (Tracker::silhouette, outline_polygons): a track that goes on through a new
// resolution or a new way of reading colours, and the object's outline.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "projtrack/tracker.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

// A reddish disc on a grey-green wall, as I420 (colours the flow model tells from the wall).
struct Picture {
  cv::Mat i420;
  int w, h;
  ColorView view() const { return test::i420_view(i420, w, h); }
  ImageView gray() const { return ImageView(i420.data, w, h, w); }
};

Picture disc(int w, int h, double cx, double cy, double r) {
  cv::Mat bgr(h, w, CV_8UC3, cv::Scalar(90, 120, 100));
  cv::circle(bgr, {static_cast<int>(std::lround(cx * 16)), static_cast<int>(std::lround(cy * 16))},
             static_cast<int>(std::lround(r * 16)), cv::Scalar(40, 60, 200), cv::FILLED,
             cv::LINE_AA, 4);
  Picture p{cv::Mat(), w, h};
  cv::cvtColor(bgr, p.i420, cv::COLOR_BGR2YUV_I420);
  return p;
}

TrackerParams manual() {
  TrackerParams tp;
  tp.acquisition = Acquisition::Manual;
  tp.smoothing = false;
  return tp;
}

TEST(Reframe, ARescaledTrackGoesOnWithoutANewAcquisition) {
  const TrackerParams tp = manual();
  Tracker t;
  t.seed({160, 120});
  TrackResult r;
  for (int i = 0; i < 3; ++i)
    r = t.track(disc(320, 240, 160, 120, 40).view(), EdgeParams{}, i / 30.0,
                Method::GapTolerantFilling, {}, tp);
  ASSERT_EQ(r.status, TrackStatus::Ok) << r.detail;
  const double depth = r.pose.depth;
  int w0 = 320, h0 = 240;
  for (const auto& [w, h] : {std::pair{160, 120}, std::pair{640, 480}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    const double k = w / 320.0;  // the disc's scale in this frame
    t.rescale(w0, h0, w, h);
    w0 = w;
    h0 = h;
    ASSERT_TRUE(t.inner_point());
    EXPECT_NEAR(t.inner_point()->x, 160 * k, 2 * k + 1);
    r = t.track(disc(w, h, 160 * k, 120 * k, 40 * k).view(), EdgeParams{}, 1,
                Method::GapTolerantFilling, {}, tp);
    EXPECT_EQ(r.status, TrackStatus::Ok) << r.detail;
    EXPECT_FALSE(r.acquired);
    EXPECT_NEAR(r.features.centroid.x, 160 * k, 1.5);
    EXPECT_NEAR(r.pose.depth, depth, 0.05 * depth) << "depth goes on";
  }
}

TEST(Reframe, RelearningFindsTheObjectWhoseColoursAreReadAnotherWay) {
  const TrackerParams tp = manual();
  Tracker t;
  t.seed({160, 120});
  const Picture colour = disc(320, 240, 160, 120, 40);
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(
        t.track(colour.view(), EdgeParams{}, i / 30.0, Method::GapTolerantFilling, {}, tp).status,
        TrackStatus::Ok);
  // The same picture, gray: colours learned from chroma mean nothing to it.
  t.relearn();
  const TrackResult r =
      t.track(colour.gray(), EdgeParams{}, 0.1, Method::GapTolerantFilling, {}, tp);
  EXPECT_EQ(r.status, TrackStatus::Ok) << r.detail;
  EXPECT_FALSE(r.acquired);
  EXPECT_NEAR(r.features.centroid.x, 160, 1.5);
}

// A disc moving to the right, at `k` times the 360×240 scene's size on frame `i`.
Picture moving_disc(int i, double k) {
  return disc(static_cast<int>(std::lround(360 * k)), static_cast<int>(std::lround(240 * k)),
              (120 + 1.5 * i) * k, 120 * k, 40 * k);
}

// One frame of `p` at `t` seconds, as the tests above track theirs.
TrackResult track(Tracker& tracker, const Picture& p, double t, const TrackerParams& tp) {
  return tracker.track(p.view(), EdgeParams{}, t, Method::GapTolerantFilling, {}, tp);
}

// Issue 32 item 4: a resize at any point of the track's life (after 1, 2, 5, 20, 60 frames; down
// and up by 2× and 3×) keeps it, its area continuous once scaled.
TEST(Reframe, AResizeAtAnyFrameKeepsTheTrack) {
  const TrackerParams tp = manual();
  for (const int after : {1, 2, 5, 20, 60}) {
    for (const double k : {0.5, 1.0 / 3, 2.0, 3.0}) {
      SCOPED_TRACE("after " + std::to_string(after) + " frames, x" + std::to_string(k));
      Tracker t;
      t.seed({120, 120});
      TrackResult r;
      for (int i = 0; i < after; ++i) r = track(t, moving_disc(i, 1), i / 30.0, tp);
      ASSERT_EQ(r.status, TrackStatus::Ok) << r.detail;
      double area = r.features.area * k * k;
      const Picture p = moving_disc(after, k);
      t.rescale(360, 240, p.w, p.h);
      int ok = 0;
      for (int i = after; i < after + 20; ++i) {
        r = track(t, moving_disc(i, k), i / 30.0, tp);
        if (r.status != TrackStatus::Ok) continue;
        ++ok;
        EXPECT_NEAR(r.features.area, area, 0.25 * area) << "frame " << i;
        EXPECT_NEAR(r.features.centroid.x, (120 + 1.5 * i) * k, 2 * k + 1) << "frame " << i;
        area = r.features.area;
      }
      EXPECT_GE(ok, 18);
    }
  }
}

// A disc moving to the right as moving_disc(), with a blue square where it was on frame `was`.
Picture disc_beside_a_square(int i, int was, double k) {
  cv::Mat bgr(static_cast<int>(std::lround(240 * k)), static_cast<int>(std::lround(360 * k)),
              CV_8UC3, cv::Scalar(90, 120, 100));
  const double x = (120 + 1.5 * was) * k, y = 120 * k, r = 40 * k;
  cv::rectangle(bgr, cv::Rect2d(x, y - r, r, 2 * r), cv::Scalar(200, 70, 40), cv::FILLED);
  cv::circle(bgr,
             {static_cast<int>(std::lround((120 + 1.5 * i) * k * 16)),
              static_cast<int>(std::lround(y * 16))},
             static_cast<int>(std::lround(r * 16)), cv::Scalar(40, 60, 200), cv::FILLED,
             cv::LINE_AA, 4);
  Picture p{cv::Mat(), bgr.cols, bgr.rows};
  cv::cvtColor(bgr, p.i420, cv::COLOR_BGR2YUV_I420);
  return p;
}

// A resize as the picture jumps back (a clip joined to another at another size): the disc, back
// by most of its radius, is found where it now is and followed on, a blue square where it was not
// taken. (The cup clip joined to itself, tests/python/test_parity.py, is the case a relearn within
// the last box lost.)
TEST(Reframe, AResizeWithAJumpInThePictureKeepsTheTrack) {
  const TrackerParams tp = manual();
  const int was = 25;
  for (const double k : {0.5, 2.0}) {
    SCOPED_TRACE("x" + std::to_string(k));
    Tracker t;
    t.seed({120, 120});
    TrackResult r;
    for (int i = 0; i < was; ++i) r = track(t, moving_disc(i, 1), i / 30.0, tp);
    ASSERT_EQ(r.status, TrackStatus::Ok) << r.detail;
    const double area = r.features.area * k * k;
    const Picture p = disc_beside_a_square(0, was, k);
    t.rescale(360, 240, p.w, p.h);
    int ok = 0;
    for (int i = 0; i < 20; ++i) {
      r = track(t, disc_beside_a_square(i, was, k), 2 + i / 30.0, tp);
      if (r.status != TrackStatus::Ok) continue;
      ++ok;
      EXPECT_NEAR(r.features.area, area, 0.25 * area) << "frame " << i;
      EXPECT_NEAR(r.features.centroid.x, (120 + 1.5 * i) * k, 2 * k + 1) << "frame " << i;
    }
    EXPECT_GE(ok, 18) << r.detail;
  }
}

// The start within the box after a rescale continues the track: a sliver of the object there (a
// hand over all but a spot of it) is refused rather than taken as the track's size, which every
// next frame's estimate would then "jump" from, losing the object for good.
TEST(Reframe, TheStartAfterARescaleContinuesTheTrack) {
  const TrackerParams tp = manual();
  Tracker t;
  t.seed({160, 120});
  TrackResult r;
  for (int i = 0; i < 20; ++i) r = track(t, disc(320, 240, 160, 120, 40), i / 30.0, tp);
  ASSERT_EQ(r.status, TrackStatus::Ok) << r.detail;
  const double area = r.features.area / 4;
  t.rescale(320, 240, 160, 120);
  r = track(t, disc(160, 120, 80, 60, 3), 1, tp);
  EXPECT_NE(r.status, TrackStatus::Ok) << "a sliver of " << r.features.area << " px² taken";
  int ok = 0;
  for (int i = 0; i < 10; ++i) {
    r = track(t, disc(160, 120, 80, 60, 20), 1.1 + i / 30.0, tp);
    if (r.status != TrackStatus::Ok) continue;
    ++ok;
    EXPECT_NEAR(r.features.area, area, 0.25 * area);
  }
  EXPECT_GE(ok, 9) << r.detail;
}

TEST(Reframe, TheSilhouetteAndItsOutline) {
  const TrackerParams tp = manual();
  Tracker t;
  EXPECT_TRUE(t.silhouette().empty());
  t.seed({160, 120});
  const TrackResult r = t.track(disc(320, 240, 160, 120, 40).view(), EdgeParams{}, 0,
                                Method::GapTolerantFilling, {}, tp);
  ASSERT_EQ(r.status, TrackStatus::Ok) << r.detail;
  const SilhouetteMask s = t.silhouette();
  ASSERT_FALSE(s.empty());
  EXPECT_TRUE(s.contains({160, 120}));
  EXPECT_FALSE(s.contains({10, 10}));
  EXPECT_FALSE(s.contains({-5, 120}));
  const std::vector<std::vector<Point2i>> outline = outline_polygons(s);
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_GE(outline[0].size(), 8u);
  EXPECT_LE(outline[0].size(), 64u) << "simplified";
  for (const Point2i& p : outline[0])
    EXPECT_NEAR(std::hypot(p.x - 160, p.y - 120), 40, 3.5) << p.x << "," << p.y;
}

TEST(Reframe, OutlinePolygonsOfPiecesAtAWorkScale) {
  // Two squares of 3×3 work pixels at scale 4, the larger first; vertices at pixel centres.
  std::vector<std::uint8_t> mask(10 * 5, 0);
  for (int y = 1; y < 4; ++y)
    for (int x = 5; x < 9; ++x) mask[y * 10 + x] = 1;
  mask[2 * 10 + 1] = 1;
  const SilhouetteMask s{ImageView(mask.data(), 10, 5, 10), Rect{2, 3, 10, 5}, 4, 64, 40};
  const std::vector<std::vector<Point2i>> outline = outline_polygons(s);
  ASSERT_EQ(outline.size(), 2u);
  ASSERT_EQ(outline[0].size(), 4u);
  for (const Point2i& p : outline[0]) {
    EXPECT_TRUE(p.x == (2 + 5) * 4 + 2 || p.x == (2 + 8) * 4 + 2) << p.x;
    EXPECT_TRUE(p.y == (3 + 1) * 4 + 2 || p.y == (3 + 3) * 4 + 2) << p.y;
  }
  ASSERT_EQ(outline[1].size(), 1u);  // a single work pixel
  EXPECT_EQ(outline[1][0].x, (2 + 1) * 4 + 2);
  EXPECT_EQ(outline[1][0].y, (3 + 2) * 4 + 2);
  EXPECT_TRUE(outline_polygons(SilhouetteMask{}).empty());
}

}  // namespace
}  // namespace projtrack
