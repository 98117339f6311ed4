// MultiTracker: several objects on one frame's evidence, each with its id; starts refused with a
// reason; objects that cross (the one behind reported occluded, never given the other's pixels,
// found again when it comes out); one object as a Tracker follows it; the frame's budget shared.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <set>
#include <vector>

#include "projtrack/multi_tracker.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

constexpr int kW = 320, kH = 240;

// An object of the scene on one frame: its pixels and where they are.
struct Truth {
  cv::Mat inside;
  Point2d centroid;
  double area = 0;
  Rect box;
};

// A frame with two ellipses over a softly textured grey: an orange one (0) moving right and a
// blue one (1) moving left, `dy` rows apart; the orange one is drawn last, in front. `step`: px a
// frame each moves.
struct TwoObjects {
  cv::Mat i420, gray;
  Truth object[2];
  ColorView view() const { return test::i420_view(i420, kW, kH); }
};

Truth truth_of(cv::Mat inside) {
  Truth t;
  const cv::Moments m = cv::moments(inside, true);
  t.area = m.m00;
  if (m.m00 > 0) t.centroid = {m.m10 / m.m00, m.m01 / m.m00};
  const cv::Rect b = cv::boundingRect(inside);
  t.box = {b.x, b.y, b.width, b.height};
  t.inside = inside;
  return t;
}

TwoObjects two_objects(int i, int dy, double step = 3, bool orange_shown = true) {
  cv::Mat bgr(kH, kW, CV_8UC3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const int t = 90 + static_cast<int>(25 * std::sin(x * 0.21) * std::cos(y * 0.17));
      bgr.at<cv::Vec3b>(y, x) = {static_cast<std::uint8_t>(t), static_cast<std::uint8_t>(t + 5),
                                 static_cast<std::uint8_t>(t + 8)};
    }
  const cv::Size axes(kW / 12, kH / 8);
  const int shift = static_cast<int>(step * i);
  const cv::Point centres[2] = {{40 + shift, kH / 2}, {kW - 40 - shift, kH / 2 + dy}};
  const cv::Scalar colours[2] = {{40, 140, 230}, {200, 90, 30}};
  cv::Mat inside[2];
  for (int k : {1, 0}) {  // the blue one first: the orange one in front
    inside[k] = cv::Mat::zeros(kH, kW, CV_8U);
    if (k == 0 && !orange_shown) continue;
    cv::ellipse(inside[k], centres[k], axes, 0, 0, 360, 255, cv::FILLED);
    bgr.setTo(colours[k], inside[k]);
  }
  inside[1].setTo(0, inside[0]);  // what shows of the blue one
  TwoObjects f;
  cv::cvtColor(bgr, f.i420, cv::COLOR_BGR2YUV_I420);
  cv::cvtColor(bgr, f.gray, cv::COLOR_BGR2GRAY);
  for (int k = 0; k < 2; ++k) f.object[k] = truth_of(inside[k]);
  return f;
}

const TrackResult* result_of(const std::vector<TrackResult>& rs, int id) {
  for (const TrackResult& r : rs)
    if (r.id == id) return &r;
  return nullptr;
}

// `f` is the object of `t`: its centroid within ¼√area of the whole object's (`whole`, px²; 0:
// t's own) and its area within ½–2× of what shows of it.
bool near(const Features& f, const Truth& t, double whole = 0) {
  return std::hypot(f.centroid.x - t.centroid.x, f.centroid.y - t.centroid.y) <
             0.25 * std::sqrt(whole > 0 ? whole : t.area) &&
         f.area > 0.5 * t.area && f.area < 2 * t.area;
}

TEST(MultiTracker, FollowsTwoObjectsEachWithItsId) {
  MultiTracker mt;
  const TwoObjects first = two_objects(0, 0);
  const Added a = mt.add_box(first.object[0].box, kW, kH);
  const Added b = mt.add_box(first.object[1].box, kW, kH);
  ASSERT_TRUE(a) << a.why;
  ASSERT_TRUE(b) << b.why;
  EXPECT_EQ(a.id, 1);
  EXPECT_EQ(b.id, 2);
  const Settings s;
  for (int i = 0; i < 25; ++i) {  // apart all along
    const TwoObjects f = two_objects(i, 0);
    const std::vector<TrackResult> rs = mt.track(f.view(), i / 30.0, s);
    ASSERT_EQ(rs.size(), 2u);
    for (int k = 0; k < 2; ++k) {
      const TrackResult& r = rs[k];
      EXPECT_EQ(r.id, k + 1);
      ASSERT_TRUE(has_features(r.status)) << i << " " << k << " " << r.detail;
      EXPECT_TRUE(near(r.features, f.object[k]))
          << "frame " << i << " object " << r.id << " at " << r.features.centroid.x << ","
          << r.features.centroid.y << " area " << r.features.area;
    }
  }
}

TEST(MultiTracker, RefusesStartsThatCannotBeNewObjectsWithAReason) {
  MultiTracker mt(2);
  const TwoObjects f = two_objects(0, 0);
  const Point2i in_orange{static_cast<int>(f.object[0].centroid.x),
                          static_cast<int>(f.object[0].centroid.y)};
  EXPECT_FALSE(mt.add_point({-1, 10}, kW, kH));
  EXPECT_FALSE(mt.add_point({kW, 10}, kW, kH));
  EXPECT_FALSE(mt.add_box({10, 10, 0, 20}, kW, kH));
  EXPECT_FALSE(mt.add_box({kW + 5, 10, 20, 20}, kW, kH));
  const cv::Mat none = cv::Mat::zeros(kH, kW, CV_8U);
  EXPECT_FALSE(mt.add_mask(ImageView(none.data, kW, kH, kW)));
  ASSERT_TRUE(mt.add_point(in_orange, kW, kH));
  const Added again = mt.add_box(f.object[0].box, kW, kH);  // the same object, not started yet
  EXPECT_FALSE(again);
  EXPECT_NE(again.why.find("object 1"), std::string::npos) << again.why;
  mt.track(f.view(), 0, Settings{});  // started: its silhouette is there
  const Added on_it = mt.add_point({in_orange.x + 5, in_orange.y}, kW, kH);
  EXPECT_FALSE(on_it);
  EXPECT_NE(on_it.why.find("object 1"), std::string::npos) << on_it.why;
  ASSERT_TRUE(mt.add_box(f.object[1].box, kW, kH));
  const Added third = mt.add_point({kW / 2, 20}, kW, kH);
  EXPECT_FALSE(third);
  EXPECT_NE(third.why.find("max objects is 2"), std::string::npos) << third.why;
  mt.set_max_objects(3);
  EXPECT_TRUE(mt.add_point({kW / 2, 20}, kW, kH)) << "one more once max objects is 3";
  mt.set_max_objects(1);
  EXPECT_EQ(mt.size(), 3u) << "the objects followed stay";
  EXPECT_FALSE(mt.add_point({kW / 2, kH - 20}, kW, kH));
  mt.set_max_objects(8);
  EXPECT_FALSE(mt.remove(7));
  EXPECT_TRUE(mt.remove(1));
  EXPECT_FALSE(mt.contains(1));
  const Added next = mt.add_point(in_orange, kW, kH);
  ASSERT_TRUE(next) << next.why;
  EXPECT_EQ(next.id, 4) << "ids are never reused";
  EXPECT_EQ(mt.ids(), (std::vector<int>{2, 3, 4}));
}

// The orange ellipse passes in front of the blue one: the blue one is occluded while hidden,
// never reported on the orange one's pixels, and found again once it is out.
TEST(MultiTracker, TheObjectBehindIsOccludedAndFoundAgain) {
  MultiTracker mt;
  const TwoObjects first = two_objects(0, 0);
  const int front = mt.add_mask(ImageView(first.object[0].inside.data, kW, kH, kW)).id;
  const int behind = mt.add_mask(ImageView(first.object[1].inside.data, kW, kH, kW)).id;
  ASSERT_GT(front, 0);
  ASSERT_GT(behind, 0);
  int occluded = 0, out_since = -1, found_after = -1;
  for (int i = 0; i < 80; ++i) {
    const TwoObjects f = two_objects(i, 0);
    const std::vector<TrackResult> rs = mt.track(f.view(), i / 30.0, Settings{});
    const TrackResult* r0 = result_of(rs, front);
    const TrackResult* r1 = result_of(rs, behind);
    ASSERT_TRUE(r0 && r1);
    EXPECT_TRUE(has_features(r0->status) && near(r0->features, f.object[0]))
        << "the object in front, frame " << i << ": " << status_name(r0->status) << " "
        << r0->detail;
    const double whole = first.object[1].area;
    const double shown = f.object[1].area / whole;
    if (shown == 0)  // wholly hidden: occluded, with its last features
      EXPECT_EQ(r1->status, TrackStatus::Occluded) << i << ": " << r1->detail;
    if (r1->status == TrackStatus::Occluded) ++occluded;
    if (has_features(r1->status))  // never the other's pixels
      EXPECT_TRUE(near(r1->features, f.object[1], whole))
          << "the object behind, frame " << i << " (" << shown << " shown) at "
          << r1->features.centroid.x << " area " << r1->features.area;
    if (shown > 0.95 && out_since < 0 && occluded > 0) out_since = i;
    if (out_since >= 0 && found_after < 0 && has_features(r1->status)) found_after = i - out_since;
  }
  EXPECT_GT(occluded, 0) << "the blue one is hidden for several frames";
  ASSERT_GE(out_since, 0);
  EXPECT_GE(found_after, 0) << "found again";
  EXPECT_LE(found_after, 10);
}

// An object gone for longer than the tracker's patience is not dropped for another: it is lost
// (no features of those frames), looked for where it was, and found again with its id.
TEST(MultiTracker, AnObjectGoneAwhileIsFoundAgainWithItsId) {
  MultiTracker mt;
  const TwoObjects first = two_objects(0, 60, 0);
  const int orange = mt.add_box(first.object[0].box, kW, kH).id;
  ASSERT_TRUE(mt.add_box(first.object[1].box, kW, kH));
  int found_after = -1;
  for (int i = 0; i < 40; ++i) {
    const bool gone = i >= 5 && i < 25;  // four times the default patience
    const TwoObjects f = two_objects(i, 60, 0, !gone);
    const std::vector<TrackResult> rs = mt.track(f.view(), i / 30.0, Settings{});
    const TrackResult* r = result_of(rs, orange);
    ASSERT_NE(r, nullptr) << i;
    if (gone) {
      EXPECT_EQ(r->status, TrackStatus::Lost) << i << ": " << r->detail;
    } else if (i >= 25 && found_after < 0 && has_features(r->status)) {
      found_after = i - 25;
      EXPECT_TRUE(near(r->features, f.object[0])) << i;
    }
  }
  EXPECT_GE(found_after, 0) << "found again";
  EXPECT_LE(found_after, 5);
}

TEST(MultiTracker, OneObjectIsFollowedAsByATracker) {
  MultiTracker mt;
  Tracker one;
  const TwoObjects first = two_objects(0, 60);
  ASSERT_TRUE(mt.add_box(first.object[0].box, kW, kH));
  one.seed_box(first.object[0].box);
  for (int i = 0; i < 20; ++i) {
    const TwoObjects f = two_objects(i, 60);
    const std::vector<TrackResult> rs = mt.track(f.view(), i / 30.0, Settings{});
    const TrackResult r = one.track(f.view(), i / 30.0, Settings{});
    ASSERT_EQ(rs.size(), 1u);
    EXPECT_EQ(rs[0].status, r.status) << i;
    EXPECT_DOUBLE_EQ(rs[0].features.area, r.features.area) << i;
    EXPECT_DOUBLE_EQ(rs[0].features.centroid.x, r.features.centroid.x) << i;
    EXPECT_EQ(rs[0].work, r.work) << i;
  }
}

// Objects of three sizes, followed at three scales (FlowModelParams::object_pixels) on a 1280×720
// frame, each learning from the work images of its own scale after every object looked: one
// frame's images hold every scale asked for until the frame ends.
TEST(MultiTracker, ObjectsOfThreeSizesAreFollowedAtTheirScales) {
  const int w = 1280, h = 720;
  const cv::Size axes[3] = {{220, 170}, {110, 90}, {36, 30}};
  const cv::Scalar colours[3] = {{40, 140, 230}, {200, 90, 30}, {60, 200, 60}};
  const auto frame = [&](int i, cv::Mat& i420, cv::Mat inside[3]) {
    cv::Mat bgr(h, w, CV_8UC3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int t = 90 + static_cast<int>(25 * std::sin(x * 0.11) * std::cos(y * 0.09));
        bgr.at<cv::Vec3b>(y, x) = {static_cast<std::uint8_t>(t), static_cast<std::uint8_t>(t),
                                   static_cast<std::uint8_t>(t + 6)};
      }
    const cv::Point centres[3] = {{300 + 3 * i, 300}, {800 - 3 * i, 250}, {1000, 560 - 2 * i}};
    for (int k = 0; k < 3; ++k) {
      inside[k] = cv::Mat::zeros(h, w, CV_8U);
      cv::ellipse(inside[k], centres[k], axes[k], 0, 0, 360, 255, cv::FILLED);
      bgr.setTo(colours[k], inside[k]);
    }
    cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  };
  MultiTracker mt;
  cv::Mat i420, inside[3];
  frame(0, i420, inside);
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(mt.add_mask(ImageView(inside[k].data, w, h, w))) << k;
  for (int i = 0; i < 10; ++i) {
    frame(i, i420, inside);
    const std::vector<TrackResult> rs = mt.track(test::i420_view(i420, w, h), i / 30.0, Settings{});
    ASSERT_EQ(rs.size(), 3u);
    std::set<int> scales;
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(has_features(rs[k].status)) << i << " " << k << ": " << rs[k].detail << " work "
                                              << rs[k].work << " of " << rs[k].work_limit;
      EXPECT_TRUE(near(rs[k].features, truth_of(inside[k]))) << i << " " << k;
      scales.insert(mt.silhouette(rs[k].id).scale);
    }
    if (i > 0) EXPECT_EQ(scales.size(), 3u) << "three scales on frame " << i;
  }
}

// Eight objects cannot take more than one frame's budget: each takes a share of what is left.
TEST(MultiTracker, EightObjectsShareOneFramesBudget) {
  MultiTracker mt(8);
  const TwoObjects first = two_objects(0, 0);
  for (int k = 0; k < 8; ++k) ASSERT_TRUE(mt.add_point({20 + 38 * k, 30}, kW, kH)) << k;
  Settings s;
  s.tracker.max_work = 2;
  std::uint64_t limit = frame_work_limit(kW, kH, s.tracker);
  for (int i = 0; i < 5; ++i) {
    const TwoObjects f = two_objects(i, 0);
    std::uint64_t spent = 0;
    for (const TrackResult& r : mt.track(f.view(), i / 30.0, s)) spent += r.work;
    EXPECT_LE(spent, limit + 8 * overshoot_bound(kW, kH)) << i;
  }
}

}  // namespace
}  // namespace projtrack
