// The object and its surroundings as mixtures of colours: a 3-D colour histogram each (16 levels
// a channel), learned at the start and followed slowly. Several colours make one object (a white
// cow's brown patches), and what tells it from its surroundings is each colour's share in both.
#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace projtrack {

class ColourMixture {
 public:
  static constexpr int kLevels = 16;  // per channel: coarse enough to learn from one frame
  static constexpr int kBins = kLevels * kLevels * kLevels;
  static constexpr int kShift = 4;  // 256 / kLevels levels per bin

  // Learns both models from `bgr` (CV_8UC3): the object where `inside` (CV_8U) is set, its
  // surroundings elsewhere. The first models are kept: they anchor later ones against drift.
  void start(const cv::Mat& bgr, const cv::Mat& inside);
  // Follows the colours at `rate` (the share of one frame): the object's where `inside` is set,
  // its surroundings' where only `around` is (CV_8U masks over `bgr`).
  void learn(const cv::Mat& bgr, const cv::Mat& inside, const cv::Mat& around, double rate);
  // Adds each pixel's log-likelihood ratio of object against surroundings to `log_odds`
  // (CV_32F): the mean of the first and the followed models, each `first_share` and the rest.
  void add_evidence(const cv::Mat& bgr, double first_share, cv::Mat& log_odds) const;
  bool learned() const { return !object_.empty(); }
  // 255 in `known` (CV_8U, `bgr`'s size) where the pixel's colour is one the object showed (the
  // first frame's or the followed model's share of it well above an unseen colour's), 0
  // elsewhere: a colour neither class has shown reads as the object's by the pseudo-counts of a
  // class of few pixels, which a search for the object must not take.
  void known_object_colours(const cv::Mat& bgr, cv::Mat& known) const;
  // The first frame's log-likelihood ratio of object against surroundings for colour `c`
  // (learned() must hold): the anchor that does not drift.
  float first_ratio(const cv::Vec3b& c) const { return first_ratio_[bin(c)]; }
  static int bin(const cv::Vec3b& c) {
    return ((c[0] >> kShift) * kLevels + (c[1] >> kShift)) * kLevels + (c[2] >> kShift);
  }
  void forget();

 private:
  using Histogram = std::vector<float>;
  // The colours where `inside` is set into `in`, the others' where `around` is (everywhere when
  // it is empty) into `out`, both normalised.
  void count(const cv::Mat& bgr, const cv::Mat& inside, const cv::Mat& around, Histogram& in,
             Histogram& out) const;

  Histogram object_, surroundings_, first_object_, first_surroundings_;
  Histogram first_ratio_;    // log(first_object_ / first_surroundings_) per colour
  float unseen_ = 0;         // the first object model's share of a colour it never showed
  Histogram in_, out_;       // one frame's counts
  mutable Histogram ratio_;  // add_evidence()'s log-likelihood ratio per colour
};

}  // namespace projtrack
