// The mask operations, region labels and work frames the object model stands on, checked against
// OpenCV's own on random masks and images.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "core/mask.hpp"
#include "core/region_labels.hpp"
#include "core/work_scale.hpp"
#include "scenes.hpp"
#include "tracker/silhouette_pieces.hpp"

namespace projtrack {
namespace {

Mask to_mask(const cv::Mat& m, Point2i origin = {0, 0}) {
  Mask out;
  out.reset({origin.x, origin.y, m.cols, m.rows});
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) out.row(y)[x] = m.at<std::uint8_t>(y, x) != 0;
  return out;
}

cv::Mat to_mat(const Mask& m) {
  cv::Mat out(m.rect().height, m.rect().width, CV_8U);
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) out.at<std::uint8_t>(y, x) = m.row(y)[x];
  return out;
}

// Blobs: random filled circles and boxes, some touching the border.
cv::Mat random_mask(std::mt19937& rng, int w, int h) {
  cv::Mat m(h, w, CV_8U, cv::Scalar(0));
  std::uniform_int_distribution<int> x(0, w - 1), y(0, h - 1), r(1, 12);
  for (int i = 0; i < 6; ++i) cv::circle(m, {x(rng), y(rng)}, r(rng), cv::Scalar(1), cv::FILLED);
  for (int i = 0; i < 3; ++i)
    cv::rectangle(m, cv::Rect(x(rng), y(rng), r(rng) * 2, r(rng)) & cv::Rect(0, 0, w, h),
                  cv::Scalar(1), cv::FILLED);
  return m;
}

TEST(Mask, DilateAndErodeAreOpenCvsWithASquare) {
  std::mt19937 rng(7);
  MaskOps ops;
  for (int trial = 0; trial < 300; ++trial) {
    // Rows wider than 8 bytes too: runs are found a word at a time.
    const int w = 1 + static_cast<int>(rng() % 150), h = 1 + static_cast<int>(rng() % 50);
    const int r = static_cast<int>(rng() % 10);
    const cv::Mat m = random_mask(rng, w, h);
    const Mask mask = to_mask(m, {5, -3});
    Mask out;
    const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, {2 * r + 1, 2 * r + 1});
    cv::Mat expect;
    cv::dilate(m, expect, kernel, {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    ops.dilate(mask, r, out);
    ASSERT_EQ(cv::countNonZero(to_mat(out) != expect), 0)
        << "dilate " << w << "x" << h << " r" << r;
    EXPECT_EQ(out.rect(), mask.rect());
    // Outside the mask counts as unset: erosion eats in from the border.
    cv::erode(m, expect, kernel, {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    ops.erode(mask, r, out);
    ASSERT_EQ(cv::countNonZero(to_mat(out) != expect), 0) << "erode " << w << "x" << h << " r" << r;
  }
}

TEST(Mask, MomentsAreOpenCvs) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 150), h = 1 + static_cast<int>(rng() % 50);
    const cv::Mat m = random_mask(rng, w, h);
    const MaskMoments got = moments(to_mask(m, {-7, 4}));
    const cv::Moments expect = cv::moments(m, true);
    ASSERT_EQ(got.area, expect.m00);
    if (expect.m00 == 0) continue;
    EXPECT_NEAR(got.centroid.x, expect.m10 / expect.m00 - 7, 1e-9);
    EXPECT_NEAR(got.centroid.y, expect.m01 / expect.m00 + 4, 1e-9);
    const cv::Rect b = cv::boundingRect(m);
    EXPECT_EQ(got.bbox, (Rect{b.x - 7, b.y + 4, b.width, b.height}));
  }
}

TEST(Mask, FillHolesKeepsWhatReachesTheBorder) {
  cv::Mat m(40, 50, CV_8U, cv::Scalar(0));
  cv::circle(m, {20, 20}, 12, cv::Scalar(1), 2);  // a ring: its inside is a hole
  // A U open at the top border: its inside reaches the border, so it is no hole.
  cv::line(m, {35, 0}, {35, 14}, cv::Scalar(1));
  cv::line(m, {44, 0}, {44, 14}, cv::Scalar(1));
  cv::line(m, {35, 14}, {44, 14}, cv::Scalar(1));
  Mask mask = to_mask(m);
  MaskOps ops;
  ops.fill_holes(mask);
  EXPECT_EQ(mask.row(20)[20], 1);  // the ring's inside is filled
  EXPECT_EQ(mask.row(5)[40], 0);   // the U's inside is not
  EXPECT_EQ(mask.row(14)[40], 1);  // the U itself stays
  EXPECT_EQ(mask.row(30)[45], 0);  // the background stays out
  // Nothing but the ring's inside was added: every added pixel is enclosed by the ring.
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 50; ++x)
      if (mask.row(y)[x] && !m.at<std::uint8_t>(y, x)) {
        ASSERT_LT(std::hypot(x - 20, y - 20), 12);
      }
}

TEST(Mask, ConvexHullIsOpenCvsFilledHull) {
  std::mt19937 rng(11);
  MaskOps ops;
  for (int trial = 0; trial < 100; ++trial) {
    const cv::Mat m = random_mask(rng, 64, 48);
    std::vector<cv::Point> points, hull;
    cv::findNonZero(m, points);
    if (points.empty()) continue;
    cv::convexHull(points, hull);
    cv::Mat expect(m.size(), CV_8U, cv::Scalar(0));
    cv::fillConvexPoly(expect, hull, cv::Scalar(1), cv::LINE_8);
    Mask out;
    ops.convex_hull(to_mask(m), out);
    // The same polygon; the rasterisations may differ only on pixels its outline passes through.
    const int differ = cv::countNonZero(to_mat(out) != expect);
    EXPECT_LE(differ, cv::arcLength(hull, true) + 8) << trial;
    for (const cv::Point& p : points) ASSERT_EQ(out.row(p.y)[p.x], 1) << "every point inside";
  }
}

TEST(RegionLabels, SamePartitionAsOpenCvs) {
  std::mt19937 rng(3);
  RegionLabels labels;
  for (int trial = 0; trial < 100; ++trial) {
    const cv::Mat m = random_mask(rng, 1 + static_cast<int>(rng() % 80), 1 + rng() % 60);
    cv::Mat cv_labels;
    const int n = cv::connectedComponents(m, cv_labels, 4, CV_32S) - 1;
    labels.label(ImageView(m.data, m.cols, m.rows, m.step), false);
    ASSERT_EQ(labels.count(), n);
    std::vector<int> map(static_cast<std::size_t>(n) + 1, -1);
    std::vector<std::int64_t> sizes(static_cast<std::size_t>(n) + 1, 0);
    for (int y = 0; y < m.rows; ++y) {
      for (int x = 0; x < m.cols; ++x) {
        const int ours = labels.row(y)[x], theirs = cv_labels.at<int>(y, x);
        ASSERT_EQ(ours == 0, theirs == 0);
        if (!ours) continue;
        if (map[ours] < 0) map[ours] = theirs;
        ASSERT_EQ(map[ours], theirs) << "one of our regions is one of theirs";
        ++sizes[ours];
      }
    }
    for (int l = 1; l <= n; ++l) EXPECT_EQ(labels.size(l), sizes[l]);
  }
}

TEST(Mask, DeepestIsTheDistanceTransformsMaximum) {
  cv::Mat m(60, 90, CV_8U, cv::Scalar(0));
  cv::rectangle(m, cv::Rect(10, 10, 70, 30), cv::Scalar(1), cv::FILLED);
  cv::circle(m, {30, 35}, 18, cv::Scalar(1), cv::FILLED);
  cv::Mat padded, dist;
  cv::copyMakeBorder(m, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::distanceTransform(padded, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  double best;
  cv::minMaxLoc(dist, nullptr, &best);
  MaskOps ops;
  const auto [p, depth] = ops.deepest(to_mask(m));
  EXPECT_NEAR(depth, best, 0.08 * best + 1);
  EXPECT_GE(dist.at<float>(p.y + 1, p.x + 1), 0.85 * best);
}

TEST(Mask, RescaleKeepsTheShape) {
  cv::Mat m(30, 40, CV_8U, cv::Scalar(0));
  cv::circle(m, {20, 15}, 10, cv::Scalar(1), cv::FILLED);
  const Mask at2 = to_mask(m, {3, 4});  // work coordinates at scale 2
  Mask at1, back;
  rescale(at2, 2, 1, at1);
  EXPECT_EQ(at1.rect(), (Rect{6, 8, 80, 60}));
  EXPECT_NEAR(moments(at1).area, 4 * moments(at2).area, 1e-9);
  rescale(at1, 1, 2, back);
  EXPECT_EQ(cv::countNonZero(to_mat(back) != m), 0);
}

// A silhouette at work scale 2 of a frame resized by 3 × 1.5, at work scale 3 of the new frame:
// 2 × 1 times as many work pixels, at the same place in the frame.
TEST(Mask, ResampleFollowsAResizedFrame) {
  cv::Mat m(30, 40, CV_8U, cv::Scalar(0));
  cv::circle(m, {20, 15}, 10, cv::Scalar(1), cv::FILLED);
  const Mask at2 = to_mask(m, {3, 4});
  Mask out;
  resample(at2, 2, 3.0, 1.5, 3, out);
  EXPECT_EQ(out.rect(), (Rect{6, 4, 80, 30}));  // frame px [6, 86) × [8, 68), ×3 × 1.5, ÷3
  const MaskMoments a = moments(at2), b = moments(out);
  EXPECT_NEAR(b.area, 2 * a.area, 0.03 * 2 * a.area);
  EXPECT_NEAR((b.centroid.x + 0.5) * 3, (a.centroid.x + 0.5) * 2 * 3, 1.5);
  EXPECT_NEAR((b.centroid.y + 0.5) * 3, (a.centroid.y + 0.5) * 2 * 1.5, 1.5);
  resample(at2, 2, 0.0, 1.0, 1, out);
  EXPECT_TRUE(out.empty()) << "a resize to nothing leaves nothing";
  resample(at2, 2, std::nan(""), 1.0, 1, out);
  EXPECT_TRUE(out.empty());
}

TEST(SilhouettePieces, ANeckSplitsTwoBlobsAndEveryPixelBelongsToOne) {
  cv::Mat m(40, 90, CV_8U, cv::Scalar(0));
  cv::circle(m, {20, 20}, 15, cv::Scalar(1), cv::FILLED);
  cv::circle(m, {68, 20}, 15, cv::Scalar(1), cv::FILLED);
  cv::rectangle(m, cv::Rect(30, 19, 30, 2), cv::Scalar(1), cv::FILLED);  // a 2 px neck
  const Mask s = to_mask(m);
  SilhouettePieces pieces;
  ASSERT_EQ(pieces.split(s, 3, 0.03), 2);
  double total = 0;
  for (int i = 0; i < 2; ++i) total += moments(pieces.piece(i)).area;
  EXPECT_EQ(total, moments(s).area);
  EXPECT_EQ(pieces.piece_at({20, 20}) == pieces.piece_at({68, 20}), false);
  EXPECT_EQ(pieces.whole(s), 1);
  EXPECT_EQ(moments(pieces.piece(0)).area, moments(s).area);
}

}  // namespace
}  // namespace projtrack
