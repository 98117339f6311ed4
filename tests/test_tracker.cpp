// The tracker: the inner point from frame to frame.
#include <gtest/gtest.h>

#include <vector>

#include "scenes.hpp"
#include "tracker.hpp"

namespace projtrack {
namespace {

TEST(Tracker, WaitsForAnInnerPoint) {
  const test::Scene disc = test::disc_scene();
  Tracker t;
  const Features f = t.track(disc.edge_view(), Method::GridFilling, {});
  EXPECT_EQ(f.status, Status::NoInnerPoint);
  EXPECT_FALSE(f.detail.empty());
  EXPECT_FALSE(t.inner_point().has_value());
}

TEST(Tracker, FollowsTheInnerPointAcrossFramesWithEveryMethod) {
  const test::Scene disc = test::disc_scene();
  for (Method m : kAllMethods) {
    Tracker t;
    t.seed({75, 80});
    const Features first = t.track(disc.edge_view(), m, {});
    ASSERT_TRUE(first.valid()) << method_name(m);
    ASSERT_TRUE(t.inner_point().has_value());
    EXPECT_EQ(*t.inner_point(), first.inner_point);
    // The next frame starts where the last one left the inner point.
    const Features second = t.track(disc.edge_view(), m, {});
    EXPECT_EQ(second.seed, first.inner_point) << method_name(m);
  }
}

TEST(Tracker, KeepsTheInnerPointWhenAnEstimateFails) {
  const test::Scene disc = test::disc_scene();
  const std::vector<std::uint8_t> all_edges(200 * 180, 255);
  Tracker t;
  t.seed({100, 90});
  EXPECT_EQ(t.track(ImageView(all_edges.data(), 200, 180, 200), Method::PixelFilling, {}).status,
            Status::InnerPointOnEdge);
  ASSERT_TRUE(t.inner_point().has_value());
  EXPECT_EQ(*t.inner_point(), (Point2i{100, 90}));
  EXPECT_TRUE(t.track(disc.edge_view(), Method::PixelFilling, {}).valid());
  t.reset();
  EXPECT_EQ(t.track(disc.edge_view(), Method::PixelFilling, {}).status, Status::NoInnerPoint);
}

}  // namespace
}  // namespace projtrack
