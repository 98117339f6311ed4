// The flow model's starts from a box and from a click (segmentation/box_start, point_start): the
// object found on textured scenes, small and large; the same cut whatever the RNG holds; nothing
// to cut on a flat picture, said at once; their work paid from the budget before each stage, the
// same on a small frame and a large one, and stopped by the budget or the stop flag.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "projtrack/color_conversion.hpp"
#include "segmentation/box_start.hpp"
#include "segmentation/point_start.hpp"

namespace projtrack {
namespace {

// A BGR picture as the tracker reads it (video range, 4:2:0 chroma), and its object.
struct Picture {
  cv::Mat bgr, truth;  // truth: CV_8U, 255 on the object
  std::vector<std::uint8_t> planes;
  ColorView view;

  Picture(cv::Mat b, cv::Mat t) : bgr(std::move(b)), truth(std::move(t)) {
    view = packed_rgb_to_color(bgr.data + 2, bgr.data + 1, bgr.data, 3,
                               static_cast<std::ptrdiff_t>(bgr.step), bgr.cols, bgr.rows, planes);
  }
  Picture(const Picture&) = delete;
  Rect box() const {
    const cv::Rect b = cv::boundingRect(truth);
    return {b.x, b.y, b.width, b.height};
  }
  Point2i centre() const {
    const cv::Moments m = cv::moments(truth, true);
    return {static_cast<int>(m.m10 / m.m00), static_cast<int>(m.m01 / m.m00)};
  }
};

// Muted blurred noise (greys and browns, a texture with edges of its own), `size`.
cv::Mat textured(cv::Size size, int seed) {
  cv::Mat noise(size, CV_8UC3), out;
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, {0, 0}, 1.5);
  noise.convertTo(out, CV_8UC3, 0.6, 60);
  return out;
}

// An ellipse of noisy orange (its own texture) on the textured background.
Picture ellipse_on_texture(cv::Size size, cv::Point centre, cv::Size axes, int seed = 7) {
  cv::Mat bgr = textured(size, seed), truth = cv::Mat::zeros(size, CV_8U);
  cv::ellipse(truth, centre, axes, 20, 0, 360, 255, cv::FILLED);
  cv::Mat object(size, CV_8UC3);
  cv::RNG rng(seed + 1);
  rng.fill(object, cv::RNG::UNIFORM, cv::Scalar(20, 110, 200), cv::Scalar(60, 160, 250));
  object.copyTo(bgr, truth);
  return {bgr, truth};
}

double iou_at(const cv::Mat& inside, const cv::Mat& truth) {
  cv::Mat up;
  cv::resize(inside, up, truth.size(), 0, 0, cv::INTER_NEAREST);
  const double both = cv::countNonZero(up & truth), either = cv::countNonZero(up | truth);
  return either > 0 ? both / either : 0;
}

cv::Size half(cv::Size s) { return {(s.width + 1) / 2, (s.height + 1) / 2}; }

TEST(ObjectInBox, TakesTheObjectNotTheBoxSmallAndLarge) {
  const cv::Size frame(320, 240);
  for (const cv::Size axes : {cv::Size(12, 8), cv::Size(40, 28), cv::Size(120, 90)}) {
    const Picture p = ellipse_on_texture(frame, {170, 118}, axes);
    CutWorkspace ws;
    WorkBudget budget;
    cv::Mat inside;
    const StartOutcome o = object_in_box(p.view, p.box(), 4000, half(frame), ws, budget, inside);
    ASSERT_EQ(o.kind, StartOutcome::Kind::Cut) << axes << ": " << o.why;
    ASSERT_EQ(inside.size(), half(frame));
    EXPECT_GT(iou_at(inside, p.truth), 0.85) << axes;
  }
}

TEST(ObjectInBox, TheBoxsCornersAreNotTheObject) {
  // A disc in a box whose corners hold blue marks seen nowhere else: the box's surroundings in
  // its corners (a kite's lines), not part of the object.
  Picture p = ellipse_on_texture({320, 240}, {160, 120}, {40, 40});
  const cv::Rect b(118, 78, 85, 85);
  cv::Mat bgr = p.bgr.clone();
  for (const cv::Point corner : {b.tl(), cv::Point(b.br().x - 12, b.y),
                                 cv::Point(b.x, b.br().y - 12), b.br() - cv::Point(12, 12)})
    cv::rectangle(bgr, cv::Rect(corner, cv::Size(12, 12)), cv::Scalar(200, 60, 30), cv::FILLED);
  const Picture marked(bgr, p.truth);
  CutWorkspace ws;
  WorkBudget budget;
  cv::Mat inside;
  ASSERT_EQ(object_in_box(marked.view, {b.x, b.y, b.width, b.height}, 4000, {320, 240}, ws, budget,
                          inside)
                .kind,
            StartOutcome::Kind::Cut);
  EXPECT_GT(iou_at(inside, p.truth), 0.9);
  EXPECT_LT(cv::countNonZero(inside(cv::Rect(b.tl(), cv::Size(12, 12)))), 10);
}

TEST(ObjectAtPoint, FindsASmallAndALargeObjectAroundTheClick) {
  // A ball of 8 px across to an ellipse a third of the frame's height: the square around the
  // click whose cut has the sharpest outline that is not the square's edge.
  const cv::Size frame(320, 240);
  for (const cv::Size axes : {cv::Size(4, 4), cv::Size(14, 10), cv::Size(60, 40)}) {
    const Picture p = ellipse_on_texture(frame, {150, 130}, axes, 11);
    CutWorkspace ws;
    WorkBudget budget;
    cv::Mat inside;
    const StartOutcome o = object_at_point(p.view, p.centre(), half(frame), ws, budget, inside);
    ASSERT_EQ(o.kind, StartOutcome::Kind::Cut) << axes << ": " << o.why << " " << int(o.kind);
    // The ball is a few work pixels: judged at the frame's size.
    cv::Mat full;
    if (axes.width < 10) {
      ASSERT_EQ(object_at_point(p.view, p.centre(), frame, ws, budget, full).kind,
                StartOutcome::Kind::Cut);
      EXPECT_GT(iou_at(full, p.truth), 0.6) << axes;
    } else {
      EXPECT_GT(iou_at(inside, p.truth), 0.8) << axes;
    }
  }
}

TEST(Starts, TheSameCutWhateverTheRNGHolds) {
  const Picture p = ellipse_on_texture({320, 240}, {150, 120}, {50, 35}, 3);
  std::vector<cv::Mat> boxes, points;
  for (const std::uint64_t state : {1ULL, 2ULL, 987654321ULL}) {
    cv::theRNG().state = state;
    CutWorkspace ws;
    WorkBudget budget;
    boxes.emplace_back();
    points.emplace_back();
    object_in_box(p.view, p.box(), 4000, {160, 120}, ws, budget, boxes.back());
    object_at_point(p.view, p.centre(), {160, 120}, ws, budget, points.back());
    EXPECT_EQ(cv::theRNG().state, state) << "the thread's generator is left as it was";
  }
  for (std::size_t i = 1; i < boxes.size(); ++i) {
    EXPECT_EQ(cv::countNonZero(boxes[i] != boxes[0]), 0) << "box, RNG state " << i;
    EXPECT_EQ(cv::countNonZero(points[i] != points[0]), 0) << "point, RNG state " << i;
  }
}

TEST(Starts, AnyBoxOrPointOnAnyFrameEndsWithAnAnswer) {
  // Boxes off the frame, of a pixel, of the whole frame; points in its corners and outside it;
  // frames of 1 × 1 and 2 × 2 pixels: a cut, nothing to cut, never a fault.
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(2, 2), cv::Size(7, 5), cv::Size(320, 240)}) {
    const Picture p = ellipse_on_texture(size, {size.width / 2, size.height / 2},
                                         {size.width / 4 + 1, size.height / 4 + 1});
    const int w = size.width, h = size.height;
    CutWorkspace ws;
    cv::Mat inside;
    for (const Rect box : {Rect{-50, -50, 20, 20}, Rect{w + 5, 0, 10, 10}, Rect{w / 2, h / 2, 1, 1},
                           Rect{0, 0, w, h}, Rect{-10, -10, w + 20, h + 20},
                           Rect{w - 1, h - 1, 1, 1}, Rect{3, 3, 0, 5}}) {
      WorkBudget budget;
      const StartOutcome o = object_in_box(p.view, box, 4000, half(size), ws, budget, inside);
      EXPECT_NE(o.kind, StartOutcome::Kind::Stopped) << size << " " << box.x << "," << box.y;
      if (o.kind == StartOutcome::Kind::Cut) {
        EXPECT_EQ(inside.size(), half(size));
      }
    }
    for (const Point2i point : {Point2i{0, 0}, Point2i{w - 1, h - 1}, Point2i{w - 1, 0},
                                Point2i{-1, 3}, Point2i{w, h}, Point2i{w / 2, h / 2}}) {
      WorkBudget budget;
      const StartOutcome o = object_at_point(p.view, point, half(size), ws, budget, inside);
      EXPECT_NE(o.kind, StartOutcome::Kind::Stopped) << size << " " << point.x << "," << point.y;
      if (o.kind == StartOutcome::Kind::Cut) {
        EXPECT_EQ(inside.size(), half(size));
      }
    }
  }
}

TEST(Starts, AGrayFrameIsCutByItsLuma) {
  const Picture p = ellipse_on_texture({320, 240}, {150, 120}, {50, 35}, 5);
  ColorView gray = p.view;
  gray.chroma = {};
  CutWorkspace ws;
  WorkBudget budget;
  cv::Mat inside;
  ASSERT_EQ(object_in_box(gray, p.box(), 4000, {320, 240}, ws, budget, inside).kind,
            StartOutcome::Kind::Cut);
  EXPECT_GT(iou_at(inside, p.truth), 0.8);
}

TEST(Starts, AFlatPictureHasNothingToCutSaidAtOnce) {
  cv::Mat noisy(480, 640, CV_8UC3);
  cv::RNG(4).fill(noisy, cv::RNG::NORMAL, 120, 1);  // sensor noise of a grey level
  for (const cv::Mat& bgr : {cv::Mat(480, 640, CV_8UC3, cv::Scalar(90, 120, 150)), noisy}) {
    const Picture p(bgr, cv::Mat::zeros(bgr.size(), CV_8U));
    CutWorkspace ws;
    WorkBudget box_budget, point_budget;
    cv::Mat inside;
    const StartOutcome box =
        object_in_box(p.view, {200, 150, 200, 150}, 4000, {320, 240}, ws, box_budget, inside);
    const StartOutcome point =
        object_at_point(p.view, {320, 240}, {320, 240}, ws, point_budget, inside);
    for (const StartOutcome& o : {box, point}) {
      EXPECT_EQ(o.kind, StartOutcome::Kind::NothingToCut);
      EXPECT_NE(o.why.find("nothing to cut"), std::string::npos) << o.why;
    }
    // Read, found flat, left: a tenth of a cut's work (the box read three times: grown twice, in
    // case it was drawn within a larger object).
    EXPECT_LT(box_budget.spent(), 500000U);
    EXPECT_LT(point_budget.spent(), 300000U);
  }
}

TEST(Starts, TheirWorkIsTheCellsNotTheFrame) {
  // The same scene at 320×240 and at 1920×1440: about the same work (the cells read are as many;
  // only the output mask, at the working size, grows).
  std::uint64_t box_work[2] = {}, point_work[2] = {};
  int k = 0;
  for (const int scale : {1, 6}) {
    const cv::Size frame(320 * scale, 240 * scale);
    const Picture p =
        ellipse_on_texture(frame, {150 * scale, 120 * scale}, {50 * scale, 35 * scale}, 9);
    CutWorkspace ws;
    WorkBudget box_budget, point_budget;
    cv::Mat inside;
    const cv::Size work(320, 240);
    ASSERT_EQ(object_in_box(p.view, p.box(), 4000, work, ws, box_budget, inside).kind,
              StartOutcome::Kind::Cut);
    ASSERT_EQ(object_at_point(p.view, p.centre(), work, ws, point_budget, inside).kind,
              StartOutcome::Kind::Cut);
    box_work[k] = box_budget.spent();
    point_work[k++] = point_budget.spent();
  }
  EXPECT_LT(static_cast<double>(box_work[1]), 1.5 * box_work[0]);
  EXPECT_LT(static_cast<double>(point_work[1]), 1.5 * point_work[0]);
  // A few million units (milliseconds): within a frame's least budget.
  EXPECT_LT(point_work[1], 8000000U);
}

TEST(Starts, StopWhereTheBudgetCannotPayAndNeverPassIt) {
  const Picture p = ellipse_on_texture({640, 480}, {300, 240}, {100, 70}, 13);
  CutWorkspace ws;
  WorkBudget full;
  cv::Mat inside;
  ASSERT_EQ(object_at_point(p.view, p.centre(), {320, 240}, ws, full, inside).kind,
            StartOutcome::Kind::Cut);
  const std::uint64_t cost = full.spent();
  for (const double share : {0.05, 0.3, 0.6, 0.95}) {
    WorkBudget some(static_cast<std::uint64_t>(share * cost));
    const StartOutcome o = object_at_point(p.view, p.centre(), {320, 240}, ws, some, inside);
    EXPECT_EQ(o.kind, StartOutcome::Kind::Stopped) << share;
    EXPECT_LE(some.spent(), some.limit()) << share << ": paid before, never past the limit";
    EXPECT_TRUE(some.ran_out()) << share;
  }
  WorkBudget box_some(200000);
  EXPECT_EQ(object_in_box(p.view, p.box(), 4000, {320, 240}, ws, box_some, inside).kind,
            StartOutcome::Kind::Stopped);
  EXPECT_LE(box_some.spent(), box_some.limit());
}

TEST(Starts, TheStopFlagStopsThemBeforeTheirNextStage) {
  const Picture p = ellipse_on_texture({640, 480}, {300, 240}, {100, 70}, 13);
  const std::atomic<bool> stop{true};
  CutWorkspace ws;
  cv::Mat inside;
  WorkBudget box_budget(WorkBudget::kUnlimited, &stop), point_budget(WorkBudget::kUnlimited, &stop);
  EXPECT_EQ(object_in_box(p.view, p.box(), 4000, {320, 240}, ws, box_budget, inside).kind,
            StartOutcome::Kind::Stopped);
  EXPECT_EQ(object_at_point(p.view, p.centre(), {320, 240}, ws, point_budget, inside).kind,
            StartOutcome::Kind::Stopped);
  EXPECT_EQ(box_budget.spent() + point_budget.spent(), 0U);
  EXPECT_FALSE(box_budget.ran_out()) << "stopped, not out of work";
}

}  // namespace
}  // namespace projtrack
