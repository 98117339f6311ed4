// Mask operations against OpenCV's, on the hand's mask at the scales the project works at, each
// into buffers made once (the outputs, kernels and point lists kept between calls): see cases.hpp.
#include <opencv2/imgproc.hpp>

#include "cases.hpp"
#include "core/region_labels.hpp"

namespace projtrack::handwritten {
namespace {

void labelling(const MaskInput& in, const Mask& m, const Effort& e, std::FILE* out) {
  RegionLabels labels;
  cv::Mat cv_labels(in.mask.size(), CV_32S), stats, centroids;
  int cv_count = 0;
  Row r{"4-connected labelling with sizes", "src/core/region_labels.cpp RegionLabels::label",
        "cv::connectedComponentsWithStats 4-connected CV_32S", in.name, ""};
  const Duel d = duel(
      [&] { labels.label(m.view(), false); },
      [&] {
        cv_count =
            cv::connectedComponentsWithStats(in.mask, cv_labels, stats, centroids, 4, CV_32S) - 1;
      },
      e.rounds, e.calls);
  r.same = labels.count() == cv_count ? "yes (" + std::to_string(cv_count) + " regions)"
                                      : "no (region counts differ)";
  write_row(out, r, d);
}

void morphology(const MaskInput& in, const Mask& m, int radius, const Effort& e, std::FILE* out) {
  MaskOps ops;
  Mask dst;
  const cv::Mat kernel =
      cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * radius + 1, 2 * radius + 1));
  cv::Mat cv_dst(in.mask.size(), CV_8U);
  const std::string k = " (2r+1)^2 square, r = " + std::to_string(radius);
  Row r{"dilate" + k, "src/core/mask.cpp MaskOps::dilate", "cv::dilate rectangular kernel", in.name,
        ""};
  Duel d = duel([&] { ops.dilate(m, radius, dst); }, [&] { cv::dilate(in.mask, cv_dst, kernel); },
                e.rounds, e.calls);
  r.same = same_pixels(to_mat(dst), cv_dst);
  write_row(out, r, d);
  r = {"erode" + k, "src/core/mask.cpp MaskOps::erode",
       "cv::erode rectangular kernel, outside unset", in.name, ""};
  d = duel([&] { ops.erode(m, radius, dst); },
           [&] {
             cv::erode(in.mask, cv_dst, kernel, {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
           },
           e.rounds, e.calls);
  r.same = same_pixels(to_mat(dst), cv_dst);
  write_row(out, r, d);
}

void hull_and_depth(const MaskInput& in, const Mask& m, const Effort& e, std::FILE* out) {
  MaskOps ops;
  Mask dst;
  std::vector<cv::Point> points, hull;
  cv::Mat cv_dst(in.mask.size(), CV_8U);
  Row r{"convex hull of a mask, filled", "src/core/mask.cpp MaskOps::convex_hull",
        "cv::findNonZero + cv::convexHull + cv::fillConvexPoly", in.name, ""};
  Duel d = duel([&] { ops.convex_hull(m, dst); },
                [&] {
                  cv::findNonZero(in.mask, points);
                  cv::convexHull(points, hull);
                  cv_dst.setTo(0);
                  cv::fillConvexPoly(cv_dst, hull, cv::Scalar(1));
                },
                e.rounds, e.calls);
  r.same = same_pixels(to_mat(dst), cv_dst);
  write_row(out, r, d);

  cv::Mat padded(in.mask.rows + 2, in.mask.cols + 2, CV_8U), dist(padded.size(), CV_32F);
  cv::Point at;
  std::pair<Point2i, double> ours;
  r = {"deepest point (chamfer distance 3-4)", "src/core/mask.cpp MaskOps::deepest",
       "cv::copyMakeBorder + cv::distanceTransform L2 mask 3 + cv::minMaxLoc", in.name, ""};
  d = duel([&] { ours = ops.deepest(m); },
           [&] {
             cv::copyMakeBorder(in.mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
             cv::distanceTransform(padded, dist, cv::DIST_L2, cv::DIST_MASK_3, CV_32F);
             cv::minMaxLoc(dist, nullptr, nullptr, nullptr, &at);
           },
           e.rounds, e.calls);
  r.same = ours.first.x == at.x - 1 && ours.first.y == at.y - 1 ? "yes (the same point)"
                                                                : "no (another point)";
  write_row(out, r, d);
}

void fill_and_moments(const MaskInput& in, const Mask& m, const Effort& e, std::FILE* out) {
  MaskOps ops;
  Mask work;
  cv::Mat padded(in.mask.rows + 2, in.mask.cols + 2, CV_8U), filled(in.mask.size(), CV_8U);
  Row r{"fill holes (0 pixels not 4-connected to the border)",
        "src/core/mask.cpp MaskOps::fill_holes",
        "cv::copyMakeBorder + cv::floodFill from the corner + cv::compare", in.name, ""};
  Duel d = duel(
      [&] {
        work = m;  // fill_holes works in place: each call on a fresh copy, as the library's
        ops.fill_holes(work);
      },
      [&] {
        cv::copyMakeBorder(in.mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
        cv::floodFill(padded, cv::Point(0, 0), cv::Scalar(2), nullptr, 0, 0, 4);
        cv::compare(padded(cv::Rect(1, 1, in.mask.cols, in.mask.rows)), 2, filled, cv::CMP_NE);
      },
      e.rounds, e.calls);
  r.same = same_pixels(to_mat(work), filled & 1);
  write_row(out, r, d);

  MaskMoments ours;
  cv::Moments theirs;
  r = {"area, centroid and box of a mask", "src/core/mask.cpp moments",
       "cv::moments binary + cv::boundingRect", in.name, ""};
  d = duel([&] { ours = moments(m); },
           [&] {
             theirs = cv::moments(in.mask, true);
             (void)cv::boundingRect(in.mask);
           },
           e.rounds, e.calls);
  r.same = ours.area == theirs.m00 ? "yes (area)" : "no (area)";
  write_row(out, r, d);
}

}  // namespace

void mask_duels(const std::vector<MaskInput>& masks, const Effort& e, std::FILE* out) {
  for (const MaskInput& in : masks) {
    Mask m;
    to_mask(in.mask, m);
    labelling(in, m, e, out);
    morphology(in, m, 1, e, out);
    morphology(in, m, 4, e, out);
    hull_and_depth(in, m, e, out);
    fill_and_moments(in, m, e, out);
  }
}

}  // namespace projtrack::handwritten
