#include "segmentation/point_start.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "segmentation/grab_cut.hpp"

namespace projtrack {

namespace {

constexpr int kRounds = 3;  // GrabCut's iterations, as in the box start
// The certain disc's radius, a share of the half-side. With only the point's 2 px certain, the
// cuts collapsed to the point on most of davis-dev (the goat at every size, the dog at all but
// the largest): the object's mixture was learned from the probable ellipse, mostly background.
constexpr double kCertain = 0.1;
constexpr double kCollapsed = 0.02;  // a cut keeping less of its square has collapsed

// GrabCut's labels for the square around `p`: certain background outside it, probable object in
// the ellipse half its size, certain object in the disc around the point.
cv::Mat seed_labels(cv::Size size, cv::Point p, int half) {
  cv::Mat labels(size, CV_8U, cv::Scalar(cv::GC_BGD));
  const cv::Rect square =
      cv::Rect(p.x - half, p.y - half, 2 * half + 1, 2 * half + 1) & cv::Rect({0, 0}, size);
  labels(square).setTo(cv::GC_PR_BGD);
  cv::Mat core = cv::Mat::zeros(size, CV_8U);
  cv::ellipse(core, p, {std::max(1, half / 2), std::max(1, half / 2)}, 0, 0, 360, 255, cv::FILLED);
  labels.setTo(cv::GC_PR_FGD, core & (labels == cv::GC_PR_BGD));
  const int certain = std::max(2, static_cast<int>(kCertain * half));
  cv::circle(labels, p, certain, cv::GC_FGD, cv::FILLED);
  return labels;
}

// Intersection over union of two CV_8U masks.
double iou(const cv::Mat& a, const cv::Mat& b) {
  const int both = cv::countNonZero(a & b);
  const int either = cv::countNonZero(a | b);
  return either > 0 ? static_cast<double>(both) / either : 0;
}

}  // namespace

std::vector<cv::Mat> objects_at_point(const WorkImages& img, cv::Point p,
                                      const std::vector<int>& halves) {
  std::vector<cv::Mat> found;
  const cv::Rect frame({0, 0}, img.bgr.size());
  for (const int half : halves) {
    cv::Mat labels = seed_labels(img.bgr.size(), p, half);
    // GrabCut reads the square and as much around it again: the background it learns from.
    const int reach = 3 * half;
    const cv::Rect roi = cv::Rect(p.x - reach, p.y - reach, 2 * reach + 1, 2 * reach + 1) & frame;
    cv::Mat sub = labels(roi).clone();
    // A cut that keeps hardly more than the disc it was told is certain has collapsed too: on a
    // small frame the disc alone is over 2 % of the smallest square (the real set's white ellipse
    // at half size: a 13-pixel start on an object of 13 000 pixels).
    const int certain = cv::countNonZero(sub == cv::GC_FGD);
    found.emplace_back();
    if (!grab_cut(img.bgr(roi), sub, cv::Rect(), kRounds)) continue;  // one colour: nothing to cut
    cv::Mat object = cv::Mat::zeros(img.bgr.size(), CV_8U), pieces;
    object(roi).setTo(255, (sub & 1) != 0);
    cv::connectedComponents(object, pieces, 8, CV_32S);
    const int at = pieces.at<int>(p);
    if (at > 0) object.setTo(0, pieces != at);
    const double square = (2.0 * half + 1) * (2.0 * half + 1);
    const double least = std::max(kCollapsed * square, 2.0 * certain);
    if (at > 0 && cv::countNonZero(object) >= least) found.back() = object;
  }
  return found;
}

int most_agreed(const std::vector<cv::Mat>& candidates) {
  int best = -1;
  double most = -1;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].empty()) continue;
    double agreement = 0;
    for (std::size_t j = 0; j < candidates.size(); ++j)
      if (j != i && !candidates[j].empty()) agreement += iou(candidates[i], candidates[j]);
    if (agreement >= most) most = agreement, best = static_cast<int>(i);
  }
  return best;
}

}  // namespace projtrack
