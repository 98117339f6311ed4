// Ray casting and the inner-point primitives.
#include <gtest/gtest.h>

#include <vector>

#include "projtrack/inner_point.hpp"
#include "projtrack/rays.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

struct Canvas {
  Canvas(int w, int h) : w(w), h(h), px(static_cast<std::size_t>(w) * h, 0) {}
  void set(int x, int y) { px[y * w + x] = 255; }
  ImageView view() const { return ImageView(px.data(), w, h, w); }
  int w, h;
  std::vector<std::uint8_t> px;
};

TEST(RayFan, DirectionsAreEvenlySpreadStartingAlongX) {
  RayFan fan;
  fan.set_count(4);
  Canvas c(21, 21);
  const RayHit right = fan.cast(c.view(), {10, 10}, 0);
  const RayHit down = fan.cast(c.view(), {10, 10}, 1);
  const RayHit left = fan.cast(c.view(), {10, 10}, 2);
  const RayHit up = fan.cast(c.view(), {10, 10}, 3);
  EXPECT_EQ(right.last_free, (Point2i{20, 10}));
  EXPECT_EQ(down.last_free, (Point2i{10, 20}));
  EXPECT_EQ(left.last_free, (Point2i{0, 10}));
  EXPECT_EQ(up.last_free, (Point2i{10, 0}));
  EXPECT_TRUE(right.at_border);
  EXPECT_DOUBLE_EQ(right.hit.x, 20.5);  // the frame border lies half a pixel past the last pixel
  EXPECT_EQ(right.length, 10);
}

TEST(RayFan, StopsAtTheFirstEdgePixel) {
  Canvas c(30, 20);
  for (int y = 0; y < 20; ++y) c.set(15, y);
  RayFan fan;
  fan.set_count(8);
  const RayHit h = fan.cast(c.view(), {10, 10}, 0);
  EXPECT_FALSE(h.at_border);
  EXPECT_EQ(h.last_free, (Point2i{14, 10}));
  EXPECT_DOUBLE_EQ(h.hit.x, 14.5);
  EXPECT_EQ(h.length, 4);
}

TEST(RayFan, CannotSlipThroughAnEightConnectedDiagonalLine) {
  Canvas c(30, 30);
  for (int x = 0; x <= 21; ++x) c.set(x, 21 - x);  // x + y = 21: only diagonal neighbours
  RayFan fan;
  fan.set_count(8);
  const RayHit h = fan.cast(c.view(), {5, 5}, 1);  // 45°, straight at the line
  EXPECT_FALSE(h.at_border);
  EXPECT_LE(h.last_free.x + h.last_free.y, 21);
  EXPECT_EQ(h.last_free, (Point2i{10, 10}));
}

TEST(RayFan, VisitsEveryPixelItRunsThrough) {
  Canvas c(40, 40);
  RayFan fan;
  fan.set_count(16);
  for (int k = 0; k < 16; ++k) {
    int visited = 0;
    const RayHit h = fan.cast(c.view(), {20, 20}, k, [&](int x, int y) {
      EXPECT_TRUE(c.view().contains(x, y));
      ++visited;
    });
    EXPECT_EQ(visited, h.length + 1);
  }
}

TEST(RayFan, FanAreaOfAnOpenFrameIsTheFrame) {
  Canvas c(101, 101);
  RayFan fan;
  fan.set_count(64);
  std::vector<RayHit> hits;
  Work work;
  const Point2d mean = cast_fan(c.view(), {50, 50}, fan, hits, work);
  EXPECT_NEAR(mean.x, 50.0, 1e-9);
  EXPECT_NEAR(mean.y, 50.0, 1e-9);
  EXPECT_NEAR(fan_area(hits.data(), 64, {50, 50}) / (101.0 * 101.0), 1.0, 0.01);
  EXPECT_EQ(work.rays, 64u);
}

TEST(MoveToward, ReachesAFreeTargetAndStopsBeforeAnEdge) {
  Canvas c(40, 20);
  Work work;
  EXPECT_EQ(move_toward(c.view(), {2, 3}, {30, 17}, work), (Point2i{30, 17}));
  EXPECT_EQ(move_toward(c.view(), {5, 5}, {5, 5}, work), (Point2i{5, 5}));
  for (int y = 0; y < 20; ++y) c.set(20, y);
  EXPECT_EQ(move_toward(c.view(), {2, 10}, {30, 10}, work), (Point2i{19, 10}));
  // Outside targets: it stops at the frame border.
  EXPECT_EQ(move_toward(c.view(), {2, 10}, {-50, 10}, work), (Point2i{0, 10}));
}

TEST(NearestFreePixel, PicksTheClosestWithinTheRadius) {
  Canvas c(20, 20);
  for (int y = 5; y <= 15; ++y)
    for (int x = 5; x <= 15; ++x) c.set(x, y);
  c.px[10 * 20 + 13] = 0;  // a hole 3 px right of the centre
  EXPECT_EQ(nearest_free_pixel(c.view(), {10, 10}, 4), (Point2i{13, 10}));
  EXPECT_FALSE(nearest_free_pixel(c.view(), {10, 10}, 2).has_value());
  EXPECT_EQ(nearest_free_pixel(c.view(), {2, 2}, 0), (Point2i{2, 2}));
}

TEST(Recentre, StaysInTheRingInsteadOfJumpingIntoItsHole) {
  const test::Scene ring = test::ring_scene();
  RayFan fan;
  fan.set_count(32);
  std::vector<RayHit> scratch;
  Work work;
  for (Point2i p : test::interior_points(ring, 6)) {
    const Point2i q = recentre(ring.edge_view(), p, fan, scratch, work, nullptr, 0);
    EXPECT_TRUE(ring.is_interior(q)) << p.x << ", " << p.y << " -> " << q.x << ", " << q.y;
  }
}

}  // namespace
}  // namespace projtrack
