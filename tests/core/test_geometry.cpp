// Rect's operations, as OpenCV's cv::Rect_ has them, checked against cv::Rect itself.
#include <gtest/gtest.h>

#include <climits>
#include <opencv2/core.hpp>
#include <random>

#include "projtrack/geometry.hpp"

namespace projtrack {
namespace {

Rect from_cv(const cv::Rect& r) { return {r.x, r.y, r.width, r.height}; }

TEST(Rect, AgreesWithOpenCvOnRandomRectangles) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pos(-20, 20), size(-3, 25);
  int non_empty_intersections = 0;
  for (int i = 0; i < 20000; ++i) {
    const cv::Rect a(pos(rng), pos(rng), size(rng), size(rng));
    const cv::Rect b(pos(rng), pos(rng), size(rng), size(rng));
    const Rect pa = from_cv(a), pb = from_cv(b);
    ASSERT_EQ(pa & pb, from_cv(a & b)) << a << ' ' << b;
    non_empty_intersections += !(a & b).empty();
    if (!a.empty() && !b.empty()) {
      ASSERT_EQ(pa | pb, from_cv(a | b)) << a << ' ' << b;
    }
    const cv::Point p(pos(rng), pos(rng));
    ASSERT_EQ(pa.contains({p.x, p.y}), a.contains(p)) << a << ' ' << p;
  }
  EXPECT_GT(non_empty_intersections, 1000);
}

TEST(Rect, AnEmptyRectangleAddsNothingToAUnionAndMeetsNothing) {
  const Rect a{3, 4, 10, 5}, none{50, 50, 0, 7};
  EXPECT_EQ(a | none, a);
  EXPECT_EQ(none | a, a);
  EXPECT_EQ(a & none, Rect{});
  EXPECT_TRUE((Rect{0, 0, 5, 5} & Rect{5, 0, 5, 5}).empty());  // touching is not overlapping
}

TEST(Rect, ClipToFrameKeepsThePartInTheFrame) {
  EXPECT_EQ(clip_to_frame({-5, -5, 20, 20}, 10, 8), (Rect{0, 0, 10, 8}));
  EXPECT_EQ(clip_to_frame({3, 2, 4, 4}, 10, 8), (Rect{3, 2, 4, 4}));
  EXPECT_EQ(clip_to_frame({8, 6, 10, 10}, 10, 8), (Rect{8, 6, 2, 2}));
  EXPECT_TRUE(clip_to_frame({10, 0, 5, 5}, 10, 8).empty());
  EXPECT_TRUE(clip_to_frame({3, 2, 4, 4}, 0, 0).empty());
}

TEST(Rect, ExtremeCoordinatesGiveDefinedAnswers) {
  const Rect far{INT_MAX - 2, INT_MAX - 2, 100, 100};  // right() would overflow int
  EXPECT_TRUE(far.contains({INT_MAX, INT_MAX}));
  EXPECT_FALSE(far.contains({INT_MAX - 3, INT_MAX}));
  EXPECT_TRUE(clip_to_frame(far, 640, 480).empty());
  EXPECT_EQ((far & Rect{INT_MAX - 1, INT_MAX - 1, 1, 1}), (Rect{INT_MAX - 1, INT_MAX - 1, 1, 1}));
  const Rect u = Rect{INT_MIN, INT_MIN, 1, 1} | Rect{INT_MAX - 1, INT_MAX - 1, 1, 1};
  EXPECT_EQ(u.x, INT_MIN);
  EXPECT_EQ(u.width, INT_MAX);  // 2^32 columns, clamped to the int range
  EXPECT_FALSE(Rect{}.contains({0, 0}));
}

}  // namespace
}  // namespace projtrack
