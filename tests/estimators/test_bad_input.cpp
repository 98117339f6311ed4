// Bad input gets a defined answer from every method: a status, never a crash or a NaN.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <vector>

#include "projtrack/estimator.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

class EveryMethod : public ::testing::TestWithParam<Method> {
 protected:
  Features run(const ImageView& edges, Point2i seed, const Params& p = {}) {
    return est_->estimate(edges, seed, p);
  }
  std::unique_ptr<Estimator> est_ = make_estimator(GetParam());
};

void expect_finite(const Features& f) {
  EXPECT_TRUE(std::isfinite(f.centroid.x) && std::isfinite(f.centroid.y));
  EXPECT_TRUE(std::isfinite(f.area));
}

TEST_P(EveryMethod, EmptyImages) {
  EXPECT_EQ(run(ImageView(), {0, 0}).status, EstimateStatus::EmptyImage);
  const std::uint8_t px[4] = {};
  EXPECT_EQ(run(ImageView(px, 0, 2, 2), {0, 0}).status, EstimateStatus::EmptyImage);
  EXPECT_EQ(run(ImageView(px, 2, 0, 2), {0, 0}).status, EstimateStatus::EmptyImage);
  EXPECT_EQ(run(ImageView(px, -3, 2, 2), {0, 0}).status, EstimateStatus::EmptyImage);
}

TEST_P(EveryMethod, StrideSmallerThanWidthIsRefused) {
  const std::vector<std::uint8_t> px(100, 0);
  const Features f = run(ImageView(px.data(), 10, 10, 9), {5, 5});
  EXPECT_EQ(f.status, EstimateStatus::InvalidImage);
  EXPECT_FALSE(f.detail.empty());
}

TEST_P(EveryMethod, OnePixelImages) {
  const std::uint8_t free_px = 0, edge_px = 255;
  const Features f = run(ImageView(&free_px, 1, 1, 1), {0, 0});
  ASSERT_EQ(f.status, EstimateStatus::CoversFrame);
  EXPECT_NEAR(f.centroid.x, 0.0, 1e-9);
  EXPECT_NEAR(f.centroid.y, 0.0, 1e-9);
  EXPECT_EQ(f.bbox, (Rect{0, 0, 1, 1}));
  EXPECT_EQ(f.inner_point, (Point2i{0, 0}));
  expect_finite(f);
  EXPECT_EQ(run(ImageView(&edge_px, 1, 1, 1), {0, 0}).status, EstimateStatus::InnerPointOnEdge);
}

TEST_P(EveryMethod, NoEdgesFillsTheWholeFrameAndSaysSo) {
  const std::vector<std::uint8_t> px(50 * 40, 0);
  const ImageView v(px.data(), 50, 40, 50);
  const Features f = run(v, {10, 30});
  ASSERT_EQ(f.status, EstimateStatus::CoversFrame);
  EXPECT_EQ(f.bbox, (Rect{0, 0, 50, 40}));
  expect_finite(f);
  if (GetParam() == Method::PixelFilling) {
    EXPECT_EQ(f.area, 2000.0);
    EXPECT_DOUBLE_EQ(f.centroid.x, 24.5);
    EXPECT_DOUBLE_EQ(f.centroid.y, 19.5);
  }
}

TEST_P(EveryMethod, AllEdgesHasNoFreePixel) {
  const std::vector<std::uint8_t> px(30 * 20, 255);
  const Features f = run(ImageView(px.data(), 30, 20, 30), {15, 10});
  EXPECT_EQ(f.status, EstimateStatus::InnerPointOnEdge);
  EXPECT_FALSE(f.valid());
  EXPECT_FALSE(f.detail.empty());
}

TEST_P(EveryMethod, InnerPointOutsideTheFrame) {
  const std::vector<std::uint8_t> px(40 * 30, 0);
  const ImageView v(px.data(), 40, 30, 40);
  // Within the seed radius of the frame: the nearest frame pixel is used.
  const Features near = run(v, {-2, 10});
  ASSERT_TRUE(near.valid());
  EXPECT_EQ(near.seed, (Point2i{0, 10}));
  // Farther, or at coordinates that would overflow: a status.
  for (Point2i p : {Point2i{-100, 10}, Point2i{10, 35}, Point2i{INT_MAX, INT_MAX},
                    Point2i{INT_MIN, 0}, Point2i{0, INT_MIN}, Point2i{INT_MAX - 2, 3}}) {
    const Features f = run(v, p);
    EXPECT_EQ(f.status, EstimateStatus::InnerPointOutside) << p.x << ", " << p.y;
  }
}

TEST_P(EveryMethod, InnerPointOnAnEdgeMovesToTheNearestFreePixel) {
  const test::Scene disc = test::disc_scene();
  const Point2i on_contour{140, 90};  // the disc's rightmost contour pixel
  ASSERT_NE(disc.edges.at<std::uint8_t>(on_contour.y, on_contour.x), 0);
  const Features f = run(disc.edge_view(), on_contour);
  ASSERT_TRUE(f.valid());
  EXPECT_EQ(distance(f.seed, on_contour), 1.0);
  EXPECT_EQ(disc.edges.at<std::uint8_t>(f.seed.y, f.seed.x), 0);
  // With no search radius there is nothing to fall back to.
  Params p;
  p.seed_radius = 0;
  EXPECT_EQ(run(disc.edge_view(), on_contour, p).status, EstimateStatus::InnerPointOnEdge);
}

TEST_P(EveryMethod, PaddedRowsGiveTheSameAnswer) {
  const test::Scene hand = test::hand_scene();
  const int w = hand.edges.cols, h = hand.edges.rows, stride = w + 13;
  std::vector<std::uint8_t> padded(static_cast<std::size_t>(stride) * h, 255);  // edge padding
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) padded[y * stride + x] = hand.edges.at<std::uint8_t>(y, x);
  const Point2i seed{130, 100};
  const Features a = run(hand.edge_view(), seed);
  const Features b = run(ImageView(padded.data(), w, h, stride), seed);
  ASSERT_TRUE(a.valid());
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.area, b.area);
  EXPECT_EQ(a.centroid.x, b.centroid.x);
  EXPECT_EQ(a.centroid.y, b.centroid.y);
  EXPECT_EQ(a.inner_point, b.inner_point);
}

TEST_P(EveryMethod, InvalidParametersAreRefusedWithAReason) {
  const test::Scene disc = test::disc_scene();
  const auto refused = [&](Params p, const char* name) {
    const Features f = run(disc.edge_view(), {100, 90}, p);
    EXPECT_EQ(f.status, EstimateStatus::InvalidParameters) << name;
    EXPECT_NE(f.detail.find(name), std::string::npos) << f.detail;
  };
  Params p;
  p.rays = 0;
  refused(p, "rays");
  p = {};
  p.grid_size = 0;
  refused(p, "grid_size");
  p = {};
  p.block_size = 0;
  refused(p, "block_size");
  p = {};
  p.recursion = 0;
  refused(p, "recursion");
  p = {};
  p.max_iterations = 0;
  refused(p, "max_iterations");
  p = {};
  p.convergence = std::nan("");
  refused(p, "convergence");
  p = {};
  p.rays = 1024;
  p.recursion = 3;
  refused(p, "rays^recursion");
}

TEST_P(EveryMethod, CellsLargerThanTheImageAreStillDefined) {
  const test::Scene disc = test::disc_scene();
  Params p;
  p.grid_size = p.block_size = 1000;
  const Features f = run(disc.edge_view(), {100, 90}, p);
  ASSERT_TRUE(f.valid());
  expect_finite(f);
  EXPECT_LE(f.area, 200.0 * 180.0);
  EXPECT_GT(f.area, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Estimators, EveryMethod, ::testing::ValuesIn(kAllMethods),
                         [](const auto& info) {
                           std::string n(method_name(info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace projtrack
