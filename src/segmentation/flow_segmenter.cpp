#include "segmentation/flow_segmenter.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "motion/motion_evidence.hpp"

namespace projtrack {

void FlowSegmenter::start(const WorkImages& img, const cv::Mat& inside) {
  scale_ = img.scale;
  cv::compare(inside, 0, mask_, cv::CMP_GT);
  mask_.convertTo(last_, CV_32F, 1.0 / 255);
  last_.copyTo(memory_);
  fullest_ = cv::sum(last_)[0];
  colours_.start(img.bgr, mask_);
  flow_.reset();
  flow_.compute(img.gray);
}

void FlowSegmenter::forget(bool colours) {
  mask_.release();
  last_.release();
  memory_.release();
  flow_.reset();
  if (colours) colours_.forget();
}

bool FlowSegmenter::follow(const WorkImages& img, const FlowModelParams& p) {
  if (last_.empty() || !flow_.compute(img.gray) || img.scale != scale_) {
    forget(false);
    return false;
  }
  predict(p);
  const double area = cv::sum(prior_)[0];
  if (area < 1) {
    forget(false);
    return false;
  }
  weigh_evidence(img, area, p);
  cv::compare(log_odds_, 0, mask_, cv::CMP_GT);
  keep_pieces_on_prior(p.keep_share);
  if (cv::countNonZero(mask_) == 0) {
    forget(false);
    return false;
  }
  colours_.learn(img.bgr, mask_, p.learning_rate);
  mask_.convertTo(last_, CV_32F, 1.0 / 255);
  remember(p);
  return true;
}

void FlowSegmenter::predict(const FlowModelParams& p) {
  carry_along_flow(last_, flow_.backward(), map_, prior_);
  cv::compare(prior_, 0.5, inside_, cv::CMP_GT);
  split_ = split_motion(flow_.backward(), inside_, p.motion_ring);
  if (!split_.valid || p.memory_weight <= 0) return;
  // The backward flow says where the object came from: it moved by the opposite.
  const cv::Matx23f move(1, 0, -split_.object.x, 0, 1, -split_.object.y);
  cv::warpAffine(memory_, moved_, move, memory_.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
  cv::swap(memory_, moved_);
  cv::multiply(memory_, p.memory_weight, moved_);
  cv::max(prior_, moved_, prior_);
}

void FlowSegmenter::remember(const FlowModelParams& p) {
  const double area = cv::sum(last_)[0];
  fullest_ = std::max(fullest_ * (1 - p.memory_fade), area);
  if (last_.size() != memory_.size() || area >= p.memory_refresh * fullest_) last_.copyTo(memory_);
}

void FlowSegmenter::weigh_evidence(const WorkImages& img, double area, const FlowModelParams& p) {
  // The prior: the carried silhouette blurred as far as the object may have moved beyond the
  // flow, as log-odds.
  const int k = static_cast<int>(p.prior_spread * std::sqrt(area)) | 1;
  if (k > 1)
    cv::GaussianBlur(prior_, log_odds_, {k, k}, 0);
  else
    prior_.copyTo(log_odds_);
  const float lo = static_cast<float>(p.prior_floor), hi = 1 - lo;
  for (int y = 0; y < log_odds_.rows; ++y) {
    float* l = log_odds_.ptr<float>(y);
    for (int x = 0; x < log_odds_.cols; ++x) {
      const float q = std::clamp(l[x], lo, hi);
      l[x] = std::log(q / (1 - q));
    }
  }
  colours_.add_evidence(img.bgr, p.first_share, log_odds_);
  add_motion_evidence(flow_.backward(), split_, p.motion_weight, p.min_separation, log_odds_);
}

void FlowSegmenter::keep_pieces_on_prior(double keep_share) {
  const int n = cv::connectedComponentsWithStats(mask_, labels_, stats_, centroids_, 8, CV_32S);
  if (n <= 2) return;  // the background and at most one piece
  std::vector<double> held(n, 0.0);
  for (int y = 0; y < labels_.rows; ++y) {
    const int* l = labels_.ptr<int>(y);
    const float* q = prior_.ptr<float>(y);
    for (int x = 0; x < labels_.cols; ++x) held[l[x]] += q[x];
  }
  held[0] = 0;
  const double least = keep_share * *std::max_element(held.begin(), held.end());
  for (int y = 0; y < labels_.rows; ++y) {
    const int* l = labels_.ptr<int>(y);
    std::uint8_t* m = mask_.ptr<std::uint8_t>(y);
    for (int x = 0; x < labels_.cols; ++x)
      if (m[x] && !(held[l[x]] > least)) m[x] = 0;
  }
}

}  // namespace projtrack
