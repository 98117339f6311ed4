// The tracker with the edges model (the paper's tracker), frame by frame: acquisition, the inner
// point, refusals, the pose. The appearance model has its own tests (test_silhouette_model.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "projtrack/edge_detection.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/tracker.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

// A bright disc on a dark frame, as gray and as Canny edges.
using Frame = test::GrayFrame;
using test::disc_frame;

// The paper's tracker: the estimator on the edges alone.
TrackerParams edges_model() {
  TrackerParams tp;
  tp.model = ObjectModelKind::Edges;
  return tp;
}

TrackerParams manual() {
  TrackerParams tp = edges_model();
  tp.acquisition = Acquisition::Manual;
  return tp;
}

TEST(Tracker, ManualWaitsForAnInnerPoint) {
  const Frame f = disc_frame(160, 120, 40);
  Tracker t;
  const TrackResult r = t.track(f.g(), f.e(), 0, Method::GridFilling, {}, manual());
  EXPECT_EQ(r.status, TrackStatus::NoInnerPoint);
  EXPECT_FALSE(r.detail.empty());
  EXPECT_FALSE(r.has_pose);
}

TEST(Tracker, FollowsTheInnerPointWithEveryMethodAndReportsThePose) {
  const Frame f = disc_frame(200, 100, 40);
  for (Method m : kAllMethods) {
    Tracker t;
    t.seed({190, 110});
    const TrackResult first = t.track(f.g(), f.e(), 0, m, {}, manual());
    ASSERT_TRUE(first.features.valid()) << method_name(m);
    EXPECT_TRUE(first.acquired);
    EXPECT_EQ(*t.inner_point(), first.features.inner_point);
    EXPECT_DOUBLE_EQ(first.raw_pose.depth, std::sqrt(first.features.area / (320.0 * 240)));
    EXPECT_NEAR(first.raw_pose.x, 2 * (first.features.centroid.x + 0.5) / 320 - 1, 1e-12);
    EXPECT_NEAR(first.raw_pose.y, 2 * (first.features.centroid.y + 0.5) / 240 - 1, 1e-12);
    const TrackResult second = t.track(f.g(), f.e(), 1.0 / 30, m, {}, manual());
    EXPECT_EQ(second.features.seed, first.features.inner_point) << method_name(m);
    EXPECT_FALSE(second.acquired);
  }
}

TEST(Tracker, DepthFollowsTheSquareRootOfTheArea) {
  TrackerParams tp = manual();
  tp.smoothing = false;
  Tracker t;
  t.seed({160, 120});
  const TrackResult first = t.track(disc_frame(160, 120, 30).g(), disc_frame(160, 120, 30).e(), 0,
                                    Method::PixelFilling, {}, tp);
  const Frame bigger = disc_frame(160, 120, 39);
  const TrackResult r = t.track(bigger.g(), bigger.e(), 0.033, Method::PixelFilling, {}, tp);
  ASSERT_EQ(r.status, TrackStatus::Ok);
  EXPECT_NEAR(r.pose.depth / first.pose.depth, 39.0 / 30.0, 0.03);  // depth ∝ √area ∝ radius
  EXPECT_EQ(r.pose.depth, r.raw_pose.depth);                        // smoothing off
}

TEST(Tracker, RefusesALeakReportsTheLastGoodFeaturesThenDropsTheTrack) {
  const Frame closed = disc_frame(160, 120, 40);
  Frame open{closed.gray.clone(), closed.edges.clone()};
  // Cut the contour: a 3 px wide vertical gap through the disc's edge on the right.
  open.edges(cv::Rect(195, 110, 10, 3)).setTo(0);
  TrackerParams tp = manual();
  tp.patience = 2;
  Tracker t;
  t.seed({160, 120});
  const TrackResult good = t.track(closed.g(), closed.e(), 0, Method::PixelFilling, {}, tp);
  ASSERT_EQ(good.status, TrackStatus::Ok) << good.detail;
  for (int i = 1; i <= 3; ++i) {
    const TrackResult r = t.track(open.g(), open.e(), i / 30.0, Method::PixelFilling, {}, tp);
    ASSERT_EQ(r.status, TrackStatus::Lost) << i;
    EXPECT_NE(r.detail.find("leak"), std::string::npos) << r.detail;
    EXPECT_EQ(r.features.area, good.features.area);  // the last good features
    EXPECT_TRUE(r.has_pose);
  }
  // Past the patience the track is dropped: manual acquisition waits again.
  EXPECT_FALSE(t.inner_point().has_value());
  EXPECT_EQ(t.track(closed.g(), closed.e(), 0.2, Method::PixelFilling, {}, tp).status,
            TrackStatus::NoInnerPoint);
}

// A leak is refused as soon as the fill passes leak_factor × the last area: it costs about the
// object's size, not the frame's.
TEST(Tracker, ALeakStopsAtTheLeakFactorInsteadOfFillingTheFrame) {
  const Frame closed = disc_frame(320, 240, 30, 1280, 720);
  Frame open{closed.gray.clone(), closed.edges.clone()};
  open.edges(cv::Rect(345, 238, 12, 5)).setTo(0);  // on the grid row through the seed
  for (Method m : {Method::PixelFilling, Method::GridFilling}) {
    Tracker t;
    t.seed({320, 240});
    const TrackResult good = t.track(closed.g(), closed.e(), 0, m, {}, manual());
    ASSERT_EQ(good.status, TrackStatus::Ok) << good.detail;
    const TrackResult r = t.track(open.g(), open.e(), 1 / 30.0, m, {}, manual());
    ASSERT_EQ(r.status, TrackStatus::Lost);
    EXPECT_NE(r.detail.find("a leak, not filled"), std::string::npos) << r.detail;
    EXPECT_EQ(r.features.area, good.features.area);
    // The full leak would visit the whole 1280×720 frame; stopped, a few times the disc.
    const Features full = make_estimator(m)->estimate(open.e(), {320, 240}, {});
    ASSERT_GT(full.area, 100 * good.features.area);
    Trace trace;
    Tracker t2;
    t2.seed({320, 240});
    t2.track(closed.g(), closed.e(), 0, m, {}, manual());
    const TrackResult r2 = t2.track(open.g(), open.e(), 1 / 30.0, m, {}, manual(), &trace);
    ASSERT_EQ(r2.status, TrackStatus::Lost);
    std::uint64_t filled = 0;
    for (const auto& run : trace.runs)
      filled +=
          static_cast<std::uint64_t>(run.last.x - run.first.x + 1) * (run.last.y - run.first.y + 1);
    EXPECT_LT(filled, 10 * good.features.area) << method_name(m);
  }
}

// Parameters nothing validates in the library (the element's properties are ranged): defined
// answers, never undefined behaviour (the sanitizer suite runs this).
TEST(Tracker, ExtremeTrackerParamsGiveDefinedAnswers) {
  const Frame f = disc_frame(160, 120, 40);
  for (double margin : {1e300, -1.0, 0.0}) {
    for (double max_area : {std::nan(""), 1e300, 0.5}) {
      TrackerParams tp = manual();
      tp.edge_margin = margin;
      tp.max_area = max_area;
      Tracker t;
      t.seed({160, 120});
      for (int i = 0; i < 3; ++i) {
        const TrackResult r =
            t.track(f.g(), EdgeParams{}, i / 30.0, Method::GapTolerantFilling, {}, tp);
        EXPECT_NE(r.status, TrackStatus::InvalidParameters) << margin << " " << max_area;
        if (r.features.valid()) {
          EXPECT_TRUE(std::isfinite(r.features.area));
        }
      }
    }
  }
}

TEST(Tracker, AUserSeedOnTheBackgroundIsRefused) {
  const Frame f = disc_frame(160, 120, 40);
  Tracker t;
  t.seed({10, 10});
  const TrackResult r = t.track(f.g(), f.e(), 0, Method::GridFilling, {}, manual());
  EXPECT_EQ(r.status, TrackStatus::Lost);
  EXPECT_NE(r.detail.find("covers"), std::string::npos) << r.detail;
  EXPECT_FALSE(r.features.valid());  // a refused estimate is never reported as a measurement
  EXPECT_FALSE(r.has_pose);
}

TEST(Tracker, CenterAcquisitionTakesWhatIsAtTheCentre) {
  TrackerParams tp = edges_model();
  tp.acquisition = Acquisition::Center;
  Tracker t;
  const Frame off = disc_frame(60, 60, 30);
  EXPECT_EQ(t.track(off.g(), off.e(), 0, Method::GridFilling, {}, tp).status,
            TrackStatus::Searching);
  const Frame centred = disc_frame(165, 115, 40);
  const TrackResult r = t.track(centred.g(), centred.e(), 0.033, Method::GridFilling, {}, tp);
  EXPECT_EQ(r.status, TrackStatus::Ok);
  EXPECT_TRUE(r.acquired);
  EXPECT_NEAR(r.features.centroid.x, 165, 2);
}

TEST(Tracker, AutoAcquisitionFindsTheMovingObject) {
  for (AutoAcquisition strategy :
       {AutoAcquisition::MotionCentroid, AutoAcquisition::CompactMovingRegion}) {
    TrackerParams tp = edges_model();
    tp.strategy = strategy;
    Tracker t;
    const Frame a = disc_frame(100, 120, 35), b = disc_frame(112, 120, 35);
    EXPECT_EQ(t.track(a.g(), a.e(), 0, Method::GridFilling, {}, tp).status, TrackStatus::Searching);
    EXPECT_EQ(t.track(a.g(), a.e(), 0.033, Method::GridFilling, {}, tp).status,
              TrackStatus::Searching)
        << "nothing moved";
    const TrackResult r = t.track(b.g(), b.e(), 0.067, Method::GridFilling, {}, tp);
    ASSERT_EQ(r.status, TrackStatus::Ok);
    EXPECT_TRUE(r.acquired);
    EXPECT_NEAR(r.features.centroid.x, 112, 2);
    EXPECT_NEAR(r.features.centroid.y, 120, 2);
  }
}

TEST(Tracker, AutoAcquisitionIgnoresSlivers) {
  // A 5 px wide bar moving: a closed region, but too thin to be an object worth tracking.
  const auto bar = [](int x) {
    cv::Mat gray(240, 320, CV_8U, cv::Scalar(40));
    gray(cv::Rect(x, 40, 5, 160)).setTo(210);
    return test::with_edges(gray);
  };
  // Every seed tried (pixel-filling's 13 fills of the background pass the default work budget
  // of a frame this small): what is judged here is what acquisition does with them.
  TrackerParams tp = edges_model();
  tp.max_work = 0;
  Tracker t;
  for (int i = 0; i < 4; ++i) {
    const Frame f = bar(100 + 6 * i);
    EXPECT_EQ(t.track(f.g(), f.e(), i / 30.0, Method::PixelFilling, {}, tp).status,
              TrackStatus::Searching)
        << i;
  }
}

}  // namespace
}  // namespace projtrack
