#include "segmentation/point_start.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "segmentation/colour_mixture.hpp"
#include "segmentation/grab_cut.hpp"

namespace projtrack {

namespace {

constexpr int kRounds = 3;  // GrabCut's iterations, as in the box start

// GrabCut's labels for the square around `p`: certain background outside it, probable object in
// the ellipse half its size, certain object at the point.
cv::Mat seed_labels(cv::Size size, cv::Point p, int half) {
  cv::Mat labels(size, CV_8U, cv::Scalar(cv::GC_BGD));
  const cv::Rect square =
      cv::Rect(p.x - half, p.y - half, 2 * half + 1, 2 * half + 1) & cv::Rect({0, 0}, size);
  labels(square).setTo(cv::GC_PR_BGD);
  cv::Mat core = cv::Mat::zeros(size, CV_8U);
  cv::ellipse(core, p, {std::max(1, half / 2), std::max(1, half / 2)}, 0, 0, 360, 255, cv::FILLED);
  labels.setTo(cv::GC_PR_FGD, core & (labels == cv::GC_PR_BGD));
  cv::circle(labels, p, 2, cv::GC_FGD, cv::FILLED);
  return labels;
}

}  // namespace

double separation_from_ring(const cv::Mat& bgr, const cv::Mat& inside) {
  const int area = cv::countNonZero(inside);
  if (area < 16) return -1;
  const int r = std::max(2, static_cast<int>(0.25 * std::sqrt(static_cast<double>(area))));
  cv::Mat ring;
  cv::dilate(inside, ring, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  ring.setTo(0, inside);
  if (cv::countNonZero(ring) == 0) return -1;
  return colour_separation(bgr, inside, ring);
}

std::vector<cv::Mat> objects_at_point(const WorkImages& img, cv::Point p,
                                      const std::vector<int>& halves) {
  std::vector<cv::Mat> found;
  const cv::Rect frame({0, 0}, img.bgr.size());
  for (const int half : halves) {
    cv::Mat labels = seed_labels(img.bgr.size(), p, half);
    // GrabCut reads the square and as much around it again: the background it learns from.
    const int reach = 3 * half;
    const cv::Rect roi = cv::Rect(p.x - reach, p.y - reach, 2 * reach + 1, 2 * reach + 1) & frame;
    cv::Mat sub = labels(roi).clone(), object;
    if (!repeatable_grab_cut(img.bgr(roi), sub, cv::Rect(), kRounds, cv::GC_INIT_WITH_MASK)) {
      found.emplace_back();
      continue;  // one colour around the point: nothing to cut
    }
    object = cv::Mat::zeros(img.bgr.size(), CV_8U);
    object(roi).setTo(255, (sub & 1) != 0);
    cv::Mat pieces;
    cv::connectedComponents(object, pieces, 8, CV_32S);
    const int at = pieces.at<int>(p);
    if (at > 0) object.setTo(0, pieces != at);
    found.push_back(object);
  }
  return found;
}

}  // namespace projtrack
