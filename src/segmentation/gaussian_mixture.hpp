// A mixture of 5 Gaussians over colours (GrabCut's colour model), fitted by EM to weighted
// colours: a start fits one to its object and one to its surroundings, on the mean colours of
// the colour bins weighted by how much of each the labels give to either, so that a fit costs
// the bins, not the pixels, and still reaches the shades between the bins it saw (davis-dev's
// kite-surf: the sea's shades differ across the box). Deterministic:
// the first fit starts from a split of the colours along their principal axis (GrabCut seeds
// k-means from the thread's random generator).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace projtrack {

class GaussianMixture {
 public:
  static constexpr int kComponents = 5;

  // `steps` EM steps on `colours` weighted by `weights`, each colour spread by `spread` (a
  // variance a channel, added to every component's: what a colour stands for): from the
  // principal-axis split when `afresh` (or never fitted), else from the current components. Not
  // fitted when the weights sum to about nothing.
  void fit(const std::vector<cv::Vec3f>& colours, const std::vector<float>& weights,
           const cv::Vec3f& spread, bool afresh, int steps);
  bool fitted() const { return fitted_; }
  // The log-density of `colour` (up to a constant, the same for every mixture); each
  // component's share of it into `responsibility` when not null.
  float log_density(const cv::Vec3f& colour, float* responsibility = nullptr) const;

 private:
  // Each colour wholly in one of kComponents groups of equal weight along the principal axis.
  void split_along_principal_axis(const std::vector<cv::Vec3f>& colours,
                                  const std::vector<float>& weights, double total);
  // The components from the responsibilities (M step).
  void estimate(const std::vector<cv::Vec3f>& colours, const std::vector<float>& weights,
                const cv::Vec3f& spread, double total);

  bool fitted_ = false;
  // Per component: its mean, its inverse covariance (xx xy xz yy yz zz) and its log weight less
  // half its covariance's log-determinant.
  float mean_[kComponents][3] = {};
  float inverse_[kComponents][6] = {};
  float log_scale_[kComponents] = {};
  std::vector<float> responsibility_;  // kComponents per colour
};

}  // namespace projtrack
