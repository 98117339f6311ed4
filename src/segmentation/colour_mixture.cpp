#include "segmentation/colour_mixture.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace projtrack {

namespace {

constexpr float kPrior =
    0.1f;  // a pseudo-count per bin: an unseen colour is unlikely, not impossible

void normalise(std::vector<float>& h) {
  const double total = std::accumulate(h.begin(), h.end(), 0.0);
  for (float& v : h) v = static_cast<float>(v / total);
}

}  // namespace

void ColourMixture::count(const cv::Mat& bgr, const cv::Mat& inside, const cv::Mat& around,
                          Histogram& in, Histogram& out) const {
  in.assign(kBins, kPrior);
  out.assign(kBins, kPrior);
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(y);
    const std::uint8_t* m = inside.ptr<std::uint8_t>(y);
    const std::uint8_t* a = around.empty() ? nullptr : around.ptr<std::uint8_t>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      if (m[x])
        in[bin(p[x])] += 1;
      else if (a == nullptr || a[x])
        out[bin(p[x])] += 1;
    }
  }
  normalise(in);
  normalise(out);
}

void ColourMixture::start(const cv::Mat& bgr, const cv::Mat& inside) {
  count(bgr, inside, cv::Mat(), object_, surroundings_);
  first_object_ = object_;
  first_surroundings_ = surroundings_;
  first_ratio_.resize(kBins);
  for (int i = 0; i < kBins; ++i) first_ratio_[i] = std::log(object_[i] / surroundings_[i]);
  unseen_ = *std::min_element(object_.begin(), object_.end());
}

void ColourMixture::known_object_colours(const cv::Mat& bgr, cv::Mat& known) const {
  known.create(bgr.size(), CV_8U);
  known.setTo(0);
  if (!learned()) return;
  // Shown by at least a pixel or two: several times an unseen colour's pseudo-count.
  const float least = 4 * unseen_;
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(y);
    std::uint8_t* k = known.ptr<std::uint8_t>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const int b = bin(p[x]);
      if (first_object_[b] > least || object_[b] > least) k[x] = 255;
    }
  }
}

void ColourMixture::learn(const cv::Mat& bgr, const cv::Mat& inside, const cv::Mat& around,
                          double rate) {
  if (!learned() || cv::countNonZero(inside) == 0) return;
  count(bgr, inside, around, in_, out_);
  const auto r = static_cast<float>(rate);
  for (int i = 0; i < kBins; ++i) {
    object_[i] += r * (in_[i] - object_[i]);
    surroundings_[i] += r * (out_[i] - surroundings_[i]);
  }
}

void ColourMixture::add_evidence(const cv::Mat& bgr, double first_share, cv::Mat& log_odds) const {
  if (!learned()) return;
  // One logarithm a colour, not a pixel.
  const auto a = static_cast<float>(first_share), b = 1 - a;
  ratio_.resize(kBins);
  for (int i = 0; i < kBins; ++i) {
    const float o = a * first_object_[i] + b * object_[i];
    const float s = a * first_surroundings_[i] + b * surroundings_[i];
    ratio_[i] = std::log(o / s);
  }
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(y);
    float* l = log_odds.ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x) l[x] += ratio_[bin(p[x])];
  }
}

void ColourMixture::forget() {
  object_.clear();
  surroundings_.clear();
  first_object_.clear();
  first_surroundings_.clear();
  first_ratio_.clear();
}

}  // namespace projtrack
