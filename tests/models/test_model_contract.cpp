// The contract every object model of the table keeps (src/models/object_model.hpp), through the
// Tracker: the same starts (a mask, a box, a point, nothing), a resize, a format change, a lost
// object, blank frames, an exhausted budget and the stop flag. A new model is one row of
// object_model_table.def; these tests run it with no line added here.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "projtrack/multi_tracker.hpp"
#include "projtrack/names.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

// A frame of the contract's scene: an orange ellipse moving right over a grey, softly textured
// background; `blank` draws the whole frame one grey level instead; `size` scales the ellipse.
struct SceneFrame {
  cv::Mat i420, gray, inside;  // the frame (I420 and its luma alone), the object's pixels
  Point2d centroid;
  double area = 0;
  Rect box;

  ColorView colour() const { return test::i420_view(i420, gray.cols, gray.rows); }
  ColorView luma() const {
    return ColorView{ImageView(gray.data, gray.cols, gray.rows, gray.step)};
  }
};

SceneFrame scene_frame(int i, int w = 320, int h = 240, int blank = -1, double size = 1) {
  cv::Mat bgr(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int t = 90 + static_cast<int>(25 * std::sin(x * 0.21) * std::cos(y * 0.17));
      bgr.at<cv::Vec3b>(y, x) = {static_cast<std::uint8_t>(t), static_cast<std::uint8_t>(t + 5),
                                 static_cast<std::uint8_t>(t + 8)};
    }
  SceneFrame f;
  f.inside = cv::Mat::zeros(h, w, CV_8U);
  const cv::Point centre(static_cast<int>(w * (0.3 + 0.008 * i)), h / 2);
  const cv::Size axes(static_cast<int>(size * w / 9), static_cast<int>(size * h / 7));
  cv::ellipse(f.inside, centre, axes, 0, 0, 360, 255, cv::FILLED);
  bgr.setTo(cv::Scalar(40, 140, 230), f.inside);
  if (blank >= 0) bgr.setTo(cv::Scalar::all(blank));
  cv::cvtColor(bgr, f.i420, cv::COLOR_BGR2YUV_I420);
  cv::cvtColor(bgr, f.gray, cv::COLOR_BGR2GRAY);
  const cv::Moments m = cv::moments(f.inside, true);
  f.area = m.m00;
  f.centroid = {m.m10 / m.m00, m.m01 / m.m00};
  const cv::Rect b = cv::boundingRect(f.inside);
  f.box = {b.x, b.y, b.width, b.height};
  return f;
}

// The tracker's estimate is the object's: centroid within ¼√area, area within ½–2×.
::testing::AssertionResult on_object(const TrackResult& r, const SceneFrame& f) {
  if (!has_features(r.status))
    return ::testing::AssertionFailure()
           << "status " << status_name(r.status) << " (" << r.detail << ")";
  const double dx = r.features.centroid.x - f.centroid.x;
  const double dy = r.features.centroid.y - f.centroid.y;
  const double ratio = r.features.area / f.area;
  if (std::hypot(dx, dy) > 0.25 * std::sqrt(f.area) || ratio < 0.5 || ratio > 2)
    return ::testing::AssertionFailure()
           << "centroid off by (" << dx << ", " << dy << "), area " << ratio << "× the object's";
  return ::testing::AssertionSuccess();
}

Settings settings_for(ObjectModelKind kind) {
  Settings s;
  s.tracker.model = kind;
  s.tracker.acquisition = Acquisition::Manual;
  return s;
}

enum class StartKind { Mask, Box, Point };
const char* name_of(StartKind k) {
  return k == StartKind::Mask ? "mask" : k == StartKind::Box ? "box" : "point";
}

void start(Tracker& t, StartKind k, const SceneFrame& f) {
  switch (k) {
    case StartKind::Mask:
      ASSERT_TRUE(t.seed_mask(ImageView(f.inside.data, f.inside.cols, f.inside.rows,
                                        static_cast<std::ptrdiff_t>(f.inside.step))));
      break;
    case StartKind::Box:
      t.seed_box(f.box);
      break;
    case StartKind::Point:
      t.seed({static_cast<int>(f.centroid.x), static_cast<int>(f.centroid.y)});
      break;
  }
}

// Starts `t` from the object's box on frame 0 and follows it on frames 0 .. frames - 1.
::testing::AssertionResult follows_from_box(Tracker& t, const Settings& s, int frames) {
  t.seed_box(scene_frame(0).box);
  for (int i = 0; i < frames; ++i) {
    const SceneFrame f = scene_frame(i);
    if (auto on = on_object(t.track(f.colour(), i, s), f); !on) return on << " (frame " << i << ")";
  }
  return ::testing::AssertionSuccess();
}

class ModelContract : public ::testing::TestWithParam<ObjectModelKind> {
 protected:
  ObjectModelKind kind() const { return GetParam(); }
  std::string model() const { return nick_of(kind()); }
};

TEST_P(ModelContract, EveryStartFollowsTheObject) {
  for (StartKind k : {StartKind::Mask, StartKind::Box, StartKind::Point}) {
    Tracker t;
    const Settings s = settings_for(kind());
    start(t, k, scene_frame(0));
    for (int i = 0; i < 20; ++i) {
      const SceneFrame f = scene_frame(i);
      const TrackResult r = t.track(f.colour(), i / 30.0, s);
      EXPECT_TRUE(on_object(r, f)) << model() << " from a " << name_of(k) << ", frame " << i;
      if (i == 0) EXPECT_TRUE(r.acquired);
    }
  }
}

TEST_P(ModelContract, WithNoStartWhatMovesIsFoundAndManualWaits) {
  Settings s = settings_for(kind());
  Tracker waiting;
  const TrackResult none = waiting.track(scene_frame(0).colour(), 0, s);
  EXPECT_EQ(none.status, TrackStatus::NoInnerPoint) << model();
  s.tracker.acquisition = Acquisition::Auto;
  Tracker t;
  int found = -1;
  for (int i = 0; i < 20 && found < 0; ++i) {
    const SceneFrame f = scene_frame(i);
    if (on_object(t.track(f.colour(), i / 30.0, s), f)) found = i;
  }
  EXPECT_GE(found, 0) << model() << ": the moving object was never found";
  EXPECT_LE(found, 5) << model();
}

TEST_P(ModelContract, AResizeKeepsTheTrack) {
  Tracker t;
  const Settings s = settings_for(kind());
  ASSERT_TRUE(follows_from_box(t, s, 8)) << model();
  t.rescale(320, 240, 480, 360);
  int on = 0;
  for (int i = 8; i < 16; ++i) {
    const SceneFrame f = scene_frame(i, 480, 360);
    const TrackResult r = t.track(f.colour(), i, s);
    EXPECT_FALSE(r.acquired) << model() << ", frame " << i << ": the same track goes on";
    on += on_object(r, f);
  }
  EXPECT_GE(on, 7) << model();
}

TEST_P(ModelContract, AFormatChangeKeepsTheTrack) {
  Tracker t;
  const Settings s = settings_for(kind());
  ASSERT_TRUE(follows_from_box(t, s, 8)) << model();
  t.relearn();  // the frames are now gray
  int on = 0;
  for (int i = 8; i < 16; ++i) {
    const SceneFrame f = scene_frame(i);
    const TrackResult r = t.track(f.luma(), i, s);
    EXPECT_FALSE(r.acquired) << model() << ", frame " << i;
    on += on_object(r, f);
  }
  EXPECT_GE(on, 7) << model();
}

TEST_P(ModelContract, ABlankFrameIsNotTheObject) {
  for (int level : {0, 128, 255}) {
    Tracker t;
    const Settings s = settings_for(kind());
    ASSERT_TRUE(follows_from_box(t, s, 6)) << model();
    for (int i = 6; i < 16; ++i) {
      const TrackResult r = t.track(scene_frame(i, 320, 240, level).colour(), i, s);
      EXPECT_FALSE(has_features(r.status))
          << model() << ": a frame all " << level << " reported as the object (frame " << i
          << ", area " << r.features.area << ")";
    }
  }
}

TEST_P(ModelContract, ARefusedFrameTeachesNothing) {
  // The object swells to over 3× its area for one frame (a leak's size): the frame is refused,
  // the silhouette held is the last accepted one (not the swollen cut), and the track goes on.
  Tracker t;
  const Settings s = settings_for(kind());
  ASSERT_TRUE(follows_from_box(t, s, 6)) << model();
  const TrackResult swollen = t.track(scene_frame(6, 320, 240, -1, 1.8).colour(), 6, s);
  ASSERT_EQ(swollen.status, TrackStatus::Lost) << model() << ": " << swollen.detail;
  std::vector<std::uint8_t> mask(320 * 240);
  if (t.silhouette(mask.data(), 320, 240, 320)) {
    const double held = cv::countNonZero(cv::Mat(240, 320, CV_8U, mask.data()));
    const double area = scene_frame(6).area;
    EXPECT_GT(held, 0.5 * area) << model();
    EXPECT_LT(held, 1.5 * area) << model() << ": the refused cut was kept";
  }
  for (int i = 7; i < 12; ++i)
    EXPECT_TRUE(on_object(t.track(scene_frame(i).colour(), i, s), scene_frame(i)))
        << model() << ", frame " << i << " after the refused one";
}

TEST_P(ModelContract, AnObjectThatLeavesIsLost) {
  Tracker t;
  const Settings s = settings_for(kind());
  ASSERT_TRUE(follows_from_box(t, s, 6)) << model();
  // The object is gone: the background alone.
  cv::Mat bgr(240, 320, CV_8UC3), i420;
  SceneFrame gone = scene_frame(0);
  gone.i420 = scene_frame(200).i420;  // far right, out of the frame
  int tracking = 0;
  for (int i = 6; i < 16; ++i) tracking += has_features(t.track(gone.colour(), i, s).status);
  EXPECT_LE(tracking, 1) << model() << ": the background reported as the object";
}

TEST_P(ModelContract, AnExhaustedBudgetEndsEveryFrameWithinItsBound) {
  // The least budget a frame gets (kLeastFrameWork) holds no model's work on a 1080p frame: every
  // stage counts what it does, so each frame ends over budget, within the bound.
  for (StartKind k : {StartKind::Box, StartKind::Point}) {
    Tracker t;
    Settings s = settings_for(kind());
    s.tracker.max_work = 0.01;
    start(t, k, scene_frame(0, 1920, 1080));
    for (int i = 0; i < 3; ++i) {
      const TrackResult r = t.track(scene_frame(i, 1920, 1080).colour(), i, s);
      ASSERT_EQ(r.work_limit, kLeastFrameWork);
      EXPECT_LE(r.work, r.work_limit + overshoot_bound(1920, 1080))
          << model() << " from a " << name_of(k) << ", frame " << i;
      EXPECT_EQ(r.status, TrackStatus::OverBudget)
          << model() << " from a " << name_of(k) << ", frame " << i << ": " << status_name(r.status)
          << " after " << r.work << " work units";
    }
  }
}

TEST_P(ModelContract, TheStopFlagEndsTheFrameAndKeepsTheTrack) {
  Tracker t;
  const Settings s = settings_for(kind());
  std::atomic<bool> stop{false};
  t.set_stop_flag(&stop);
  start(t, StartKind::Box, scene_frame(0));
  for (int i = 0; i < 4; ++i)
    ASSERT_TRUE(on_object(t.track(scene_frame(i).colour(), i, s), scene_frame(i)));
  stop = true;
  const TrackResult r = t.track(scene_frame(4).colour(), 4, s);
  EXPECT_EQ(r.status, TrackStatus::Interrupted) << model();
  stop = false;
  EXPECT_TRUE(on_object(t.track(scene_frame(5).colour(), 5, s), scene_frame(5))) << model();
}

// A MultiTracker follows each object with the model as a Tracker does (its one-object results
// are a Tracker's: test_multi_tracker), and a second object beside it changes the first one's
// by little: the frame's work images it shares may be built over more of the frame for the other
// (a start reads the frame whole), which moves the outline by a pixel here and there.
TEST_P(ModelContract, AMultiTrackerFollowsEachObjectAsATracker) {
  const Settings s = settings_for(kind());
  Tracker alone;
  MultiTracker both;
  const SceneFrame first = scene_frame(0);
  alone.seed_box(first.box);
  const Added object = both.add_box(first.box, first.gray.cols, first.gray.rows);
  ASSERT_TRUE(object) << object.why;
  // The second object: a patch of the background far from the ellipse, which stays put.
  ASSERT_TRUE(both.add_point({first.gray.cols - 20, 20}, first.gray.cols, first.gray.rows));
  for (int i = 0; i < 12; ++i) {
    const SceneFrame f = scene_frame(i);
    const TrackResult r = alone.track(f.colour(), i / 30.0, s);
    const std::vector<TrackResult> rs = both.track(f.colour(), i / 30.0, s);
    ASSERT_EQ(rs.size(), 2u);
    EXPECT_EQ(rs[0].id, object.id);
    EXPECT_EQ(rs[0].status, r.status) << model() << ", frame " << i << ": " << rs[0].detail;
    EXPECT_NEAR(rs[0].features.area, r.features.area, 0.03 * r.features.area)
        << model() << ", frame " << i;
    EXPECT_TRUE(on_object(rs[0], f)) << model() << ", frame " << i;
  }
}

std::vector<ObjectModelKind> every_model() {
  std::vector<ObjectModelKind> v;
  for (const auto& row : names_of<ObjectModelKind>()) v.push_back(row.value);
  return v;
}

INSTANTIATE_TEST_SUITE_P(EveryModel, ModelContract, ::testing::ValuesIn(every_model()),
                         [](const auto& info) { return std::string(nick_of(info.param)); });

}  // namespace
}  // namespace projtrack
