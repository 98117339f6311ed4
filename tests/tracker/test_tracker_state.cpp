// The tracker's state between frames and its named transitions, and the policy's verdict after
// a refused frame (src/tracker/tracker_state.hpp, acquisition_policy.hpp).
#include <gtest/gtest.h>

#include "tracker/refusal_policy.hpp"
#include "tracker/tracker_state.hpp"

namespace projtrack {
namespace {

Features estimate_at(double x, double y, double area) {
  Features f;
  f.status = EstimateStatus::Ok;
  f.centroid = {x, y};
  f.area = area;
  f.bbox = {static_cast<int>(x) - 10, static_cast<int>(y) - 10, 20, 20};
  f.inner_point = {static_cast<int>(x), static_cast<int>(y)};
  return f;
}

TEST(TrackerState, AcceptStartsATrackOnceAndFollowsItsVelocity) {
  TrackerState s;
  const TrackerParams tp;
  s.seed({50, 60});
  EXPECT_TRUE(s.accept(estimate_at(50, 60, 400), false, 0.0, 320, 240, tp));
  EXPECT_TRUE(s.track().seeded);
  EXPECT_FALSE(s.accept(estimate_at(53, 56, 400), false, 0.04, 320, 240, tp));
  EXPECT_DOUBLE_EQ(s.track().velocity.x, 3);
  EXPECT_DOUBLE_EQ(s.track().velocity.y, -4);
  EXPECT_EQ(s.track().inner, (Point2i{53, 56}));
  EXPECT_DOUBLE_EQ(s.pointer.raw().depth, std::sqrt(400.0 / (320 * 240)));
}

TEST(TrackerState, DropRemembersWhereTheObjectWasAndResetForgetsAll) {
  TrackerState s;
  const TrackerParams tp;
  s.seed_box({40, 50, 20, 30});
  EXPECT_EQ(s.track().inner, (Point2i{50, 65}));
  ASSERT_TRUE(s.track().seed_box);
  s.accept(estimate_at(50, 65, 600), false, 0, 320, 240, tp);
  EXPECT_FALSE(s.track().seed_box) << "the box is used once";
  s.drop();
  EXPECT_FALSE(s.track().inner);
  EXPECT_FALSE(s.track().last);
  EXPECT_DOUBLE_EQ(s.track().lost_area, 600);
  s.reset();
  EXPECT_FALSE(s.track().inner);
}

TEST(TrackerState, SwitchingModelsKeepsOnlyTheUsersStart) {
  TrackerState s;
  const TrackerParams tp;
  s.seed_box({10, 20, 30, 40});
  s.switch_model();
  EXPECT_EQ(s.track().inner, (Point2i{25, 40}));
  ASSERT_TRUE(s.track().seed_box);
  s.accept(estimate_at(25, 40, 400), false, 0, 320, 240, tp);
  s.switch_model();
  EXPECT_TRUE(s.track().inner) << "the inner point the track reached";
  EXPECT_FALSE(s.track().last);
}

TEST(TrackerState, ARescaledBoxStaysWithinTheFrame) {
  // A box over the whole of a 29×25 frame: the user's (held until the track starts) and an
  // accepted estimate's.
  TrackerState held, accepted;
  const TrackerParams tp;
  held.seed_box({0, 0, 29, 25});
  Features f = estimate_at(14, 12, 29 * 25);
  f.bbox = f.reach = {0, 0, 29, 25};
  accepted.seed({14, 12});
  accepted.accept(f, false, 0, 29, 25, tp);
  // Every scaled box rounds outward, and 29 × (480 / 29) is 480 and a little in floating point:
  // after each resize the boxes must still lie within the frame.
  const int sizes[][2] = {{480, 7}, {13, 497}, {3, 8}, {276, 618}, {25, 5}, {276, 497}};
  int w = 29, h = 25;
  for (const auto& size : sizes) {
    const double sx = static_cast<double>(size[0]) / w, sy = static_cast<double>(size[1]) / h;
    w = size[0], h = size[1];
    held.rescale(sx, sy, w, h);
    accepted.rescale(sx, sy, w, h);
    const Rect frame{0, 0, w, h};
    ASSERT_TRUE(held.track().seed_box);
    ASSERT_TRUE(accepted.track().last);
    EXPECT_EQ(*held.track().seed_box & frame, *held.track().seed_box) << w << "x" << h;
    EXPECT_FALSE(held.track().seed_box->empty()) << w << "x" << h;
    EXPECT_EQ(accepted.track().last->bbox & frame, accepted.track().last->bbox) << w << "x" << h;
    EXPECT_EQ(accepted.track().last->reach & frame, accepted.track().last->reach);
  }
}

TEST(AcquisitionPolicy, PatienceRefusalsAreToleratedAndTheNextDropsTheTrack) {
  TrackerState s;
  TrackerParams tp;
  tp.patience = 3;
  s.seed({50, 50});
  s.accept(estimate_at(50, 50, 400), false, 0, 320, 240, tp);
  for (int i = 1; i <= tp.patience; ++i) {
    s.refuse();
    EXPECT_FALSE(after_refusal(s.track(), tp, false).drop) << i;
  }
  s.refuse();
  const AfterRefusal last = after_refusal(s.track(), tp, false);
  EXPECT_TRUE(last.drop);
  EXPECT_NE(last.note.find("dropped"), std::string::npos);
  EXPECT_TRUE(after_refusal(Track{}, tp, true).drop) << "forced";
}

}  // namespace
}  // namespace projtrack
