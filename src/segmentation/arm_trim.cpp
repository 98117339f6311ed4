#include "segmentation/arm_trim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

constexpr int kLevels = 8;  // colour bins a channel: the two parts hold few pixels each
constexpr int kBins = kLevels * kLevels * kLevels;
// The object's colours: within this share of the cut's √area around the click; the arm's: the
// cut's pixels within as much of the frame's border.
constexpr double kReach = 0.2;
// The part kept must hold at least this share of the cut (less: the colours parted the object
// itself, not an arm from it).
constexpr double kLeastKept = 0.2;
constexpr std::uint64_t kCostPerPixel = 8;  // the histograms, the vote, the pieces

using Histogram = std::array<float, kBins>;

int bin(const cv::Vec3b& c) {
  return ((c[0] >> 5) * kLevels + (c[1] >> 5)) * kLevels + (c[2] >> 5);
}

bool reaches_border(const cv::Mat& m) {
  return cv::countNonZero(m.row(0)) > 0 || cv::countNonZero(m.row(m.rows - 1)) > 0 ||
         cv::countNonZero(m.col(0)) > 0 || cv::countNonZero(m.col(m.cols - 1)) > 0;
}

// The colours of `mask`'s pixels where `take(x, y)`, a share each (a pixel's worth of
// pseudo-count spread over the bins).
template <class Take>
void colours_of(const cv::Mat& bgr, const cv::Mat& mask, Take take, Histogram& h) {
  h.fill(1.0f / kBins);
  double n = 1;
  for (int y = 0; y < mask.rows; ++y) {
    const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < mask.cols; ++x)
      if (m[x] && take(x, y)) h[bin(p[x])] += 1, n += 1;
  }
  for (float& v : h) v = static_cast<float>(v / n);
}

}  // namespace

bool trim_arm(const cv::Mat& bgr, cv::Point click, WorkBudget& budget, cv::Mat& mask) {
  if (mask.empty() || bgr.size() != mask.size() || !reaches_border(mask) ||
      !cv::Rect(0, 0, mask.cols, mask.rows).contains(click))
    return false;
  const std::uint64_t cost = kCostPerPixel * static_cast<std::uint64_t>(mask.total());
  if (budget.exhausted(cost)) return false;
  budget.spend(cost);
  const double area = cv::countNonZero(mask);
  const double reach = std::max(1.0, kReach * std::sqrt(area));
  const int w = mask.cols, h = mask.rows;
  Histogram object, arm;
  colours_of(
      bgr, mask, [&](int x, int y) { return std::hypot(x - click.x, y - click.y) <= reach; },
      object);
  colours_of(
      bgr, mask,
      [&](int x, int y) {
        return std::min({x, y, w - 1 - x, h - 1 - y}) < reach;
      },
      arm);
  cv::Mat kept(mask.size(), CV_8U, cv::Scalar(0)), pieces;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(y);
    std::uint8_t* k = kept.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x)
      if (m[x] && object[bin(p[x])] >= arm[bin(p[x])]) k[x] = 255;
  }
  cv::connectedComponents(kept, pieces, 8, CV_32S);
  const int label = pieces.at<int>(click);
  if (label == 0) return false;
  kept = pieces == label;
  if (reaches_border(kept) || cv::countNonZero(kept) < kLeastKept * area) return false;
  mask = kept;
  return true;
}

}  // namespace projtrack
