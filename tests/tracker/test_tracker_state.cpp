// The tracker's state between frames and its named transitions, and the policy's verdict after
// a refused frame (src/tracker/tracker_state.hpp, acquisition_policy.hpp).
#include <gtest/gtest.h>

#include "tracker/acquisition_policy.hpp"
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

TEST(TrackerState, DropKeepingColoursRemembersWhereTheObjectWasAndResetForgetsAll) {
  TrackerState s;
  const TrackerParams tp;
  s.seed_box({40, 50, 20, 30});
  EXPECT_EQ(s.track().inner, (Point2i{50, 65}));
  ASSERT_TRUE(s.track().seed_box);
  s.accept(estimate_at(50, 65, 600), false, 0, 320, 240, tp);
  EXPECT_FALSE(s.track().seed_box) << "the box is used once";
  s.drop(TrackerState::Keep::Colours);
  EXPECT_FALSE(s.track().inner);
  EXPECT_FALSE(s.track().last);
  EXPECT_DOUBLE_EQ(s.track().lost_area, 600);
  s.reset();
  EXPECT_FALSE(s.track().inner);
}

TEST(TrackerState, SwitchingModelsKeepsOnlyTheInnerPoint) {
  TrackerState s;
  s.seed({10, 20});
  s.use_model(ObjectModelKind::Edges);
  EXPECT_EQ(s.model(), ObjectModelKind::Edges);
  EXPECT_EQ(s.track().inner, (Point2i{10, 20}));
}

TEST(AcquisitionPolicy, PatienceRefusalsAreToleratedAndTheNextDropsTheTrack) {
  TrackerState s;
  TrackerParams tp;
  tp.patience = 3;
  s.seed({50, 50});
  s.accept(estimate_at(50, 50, 400), false, 0, 320, 240, tp);
  for (int i = 1; i <= tp.patience; ++i) {
    s.refuse();
    EXPECT_FALSE(after_refusal(s, tp, false).drop) << i;
  }
  s.refuse();
  const AfterRefusal last = after_refusal(s, tp, false);
  EXPECT_TRUE(last.drop);
  EXPECT_NE(last.note.find("dropped"), std::string::npos);
  EXPECT_TRUE(after_refusal(TrackerState{}, tp, true).drop) << "forced";
}

TEST(AcquisitionPolicy, AnObjectFoundByMotionRefusedOnAndOffIsAFragment) {
  TrackerParams tp;  // appearance model, unsteady = 3
  ASSERT_EQ(tp.unsteady, 3);
  for (bool seeded : {false, true}) {
    TrackerState s;
    if (seeded) s.seed({50, 50});
    s.accept(estimate_at(50, 50, 400), false, 0, 320, 240, tp);
    bool dropped = false;
    for (int i = 0; i < 3 && !dropped; ++i) {  // refused, accepted, refused, accepted, ...
      s.refuse();
      dropped = after_refusal(s, tp, false).drop;
      s.accept(estimate_at(50, 50, 400), false, 0.04 * (i + 1), 320, 240, tp);
    }
    EXPECT_EQ(dropped, !seeded) << "the user's object is never taken for a fragment";
  }
}

TEST(AcquisitionPolicy, ThresholdsShrinkWithTheScenesContrastToAThird) {
  const TrackerParams tp;
  EXPECT_EQ(motion_params(tp, 0).threshold, tp.motion.threshold) << "not measured yet";
  EXPECT_EQ(motion_params(tp, 400).threshold, tp.motion.threshold);
  EXPECT_EQ(motion_params(tp, 10).threshold,
            static_cast<int>(std::lround(tp.motion.threshold / 3.0)));
  EXPECT_LT(finder_params(tp, 95).background_change, tp.finder.background_change);
}

}  // namespace
}  // namespace projtrack
