#include "segmentation/gaussian_mixture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace projtrack {

namespace {

constexpr int kPowerSteps = 8;  // of the principal axis' power iteration

cv::Vec3d principal_axis(const std::vector<cv::Vec3f>& colours, const std::vector<float>& weights,
                         double total) {
  cv::Vec3d mean(0, 0, 0);
  for (std::size_t i = 0; i < colours.size(); ++i) mean += weights[i] * cv::Vec3d(colours[i]);
  mean /= total;
  cv::Matx33d cov = cv::Matx33d::zeros();
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const cv::Vec3d d = cv::Vec3d(colours[i]) - mean;
    cov += weights[i] * (cv::Matx31d(d) * cv::Matx13d(d[0], d[1], d[2]));
  }
  cv::Vec3d axis(1, 1, 1);
  for (int it = 0; it < kPowerSteps; ++it) {
    const cv::Vec3d next = cov * axis;
    if (cv::norm(next) < 1e-9) break;
    axis = next / cv::norm(next);
  }
  return axis;
}

}  // namespace

void GaussianMixture::split_along_principal_axis(const std::vector<cv::Vec3f>& colours,
                                                 const std::vector<float>& weights, double total) {
  const cv::Vec3d axis = principal_axis(colours, weights, total);
  const int n = static_cast<int>(colours.size());
  std::vector<std::pair<double, int>> order(n);
  for (int i = 0; i < n; ++i) order[i] = {axis.dot(cv::Vec3d(colours[i])), i};
  std::sort(order.begin(), order.end());
  double before = 0;
  for (const auto& [projection, i] : order) {
    const int k = std::min(kComponents - 1,
                           static_cast<int>(kComponents * (before + 0.5 * weights[i]) / total));
    responsibility_[i * kComponents + k] = 1;
    before += weights[i];
  }
}

void GaussianMixture::estimate(const std::vector<cv::Vec3f>& colours,
                               const std::vector<float>& weights, const cv::Vec3f& spread,
                               double total) {
  const int n = static_cast<int>(colours.size());
  for (int k = 0; k < kComponents; ++k) {
    double wk = 0, m[3] = {0, 0, 0}, c[6] = {0, 0, 0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
      const double a = weights[i] * responsibility_[i * kComponents + k];
      wk += a;
      for (int j = 0; j < 3; ++j) m[j] += a * colours[i][j];
    }
    if (wk <= 1e-9 * total) {  // an empty component takes no part
      log_scale_[k] = -1e30f;
      std::fill(mean_[k], mean_[k] + 3, 0.f);
      std::fill(inverse_[k], inverse_[k] + 6, 0.f);
      continue;
    }
    for (double& v : m) v /= wk;
    for (int i = 0; i < n; ++i) {
      const double a = weights[i] * responsibility_[i * kComponents + k];
      const double d0 = colours[i][0] - m[0], d1 = colours[i][1] - m[1], d2 = colours[i][2] - m[2];
      c[0] += a * d0 * d0, c[1] += a * d0 * d1, c[2] += a * d0 * d2;
      c[3] += a * d1 * d1, c[4] += a * d1 * d2, c[5] += a * d2 * d2;
    }
    for (double& v : c) v /= wk;
    c[0] += spread[0], c[3] += spread[1], c[5] += spread[2];
    // The symmetric 3×3 inverse by cofactors.
    const double i0 = c[3] * c[5] - c[4] * c[4], i1 = c[2] * c[4] - c[1] * c[5];
    const double i2 = c[1] * c[4] - c[2] * c[3], i3 = c[0] * c[5] - c[2] * c[2];
    const double i4 = c[1] * c[2] - c[0] * c[4], i5 = c[0] * c[3] - c[1] * c[1];
    const double det = c[0] * i0 + c[1] * i1 + c[2] * i2;
    const double inverse[6] = {i0, i1, i2, i3, i4, i5};
    for (int j = 0; j < 3; ++j) mean_[k][j] = static_cast<float>(m[j]);
    for (int j = 0; j < 6; ++j) inverse_[k][j] = static_cast<float>(inverse[j] / det);
    log_scale_[k] = static_cast<float>(std::log(wk / total) - 0.5 * std::log(det));
  }
}

void GaussianMixture::fit(const std::vector<cv::Vec3f>& colours, const std::vector<float>& weights,
                          const cv::Vec3f& spread, bool afresh, int steps) {
  double total = 0;
  for (const float w : weights) total += w;
  if (total <= 1e-6) {
    fitted_ = false;
    return;
  }
  const std::size_t n = colours.size();
  responsibility_.assign(n * kComponents, 0.f);
  if (afresh || !fitted_) {
    split_along_principal_axis(colours, weights, total);
  } else {
    for (std::size_t i = 0; i < n; ++i) log_density(colours[i], &responsibility_[i * kComponents]);
  }
  for (int step = 0; step < steps; ++step) {
    estimate(colours, weights, spread, total);
    fitted_ = true;
    if (step + 1 < steps)
      for (std::size_t i = 0; i < n; ++i)
        log_density(colours[i], &responsibility_[i * kComponents]);
  }
}

float GaussianMixture::log_density(const cv::Vec3f& x, float* responsibility) const {
  float e[kComponents], top = -std::numeric_limits<float>::infinity();
  for (int k = 0; k < kComponents; ++k) {
    const float a = x[0] - mean_[k][0], b = x[1] - mean_[k][1], c = x[2] - mean_[k][2];
    const float* q = inverse_[k];
    const float m =
        a * (q[0] * a + 2 * q[1] * b + 2 * q[2] * c) + b * (q[3] * b + 2 * q[4] * c) + c * q[5] * c;
    e[k] = log_scale_[k] - 0.5f * m;
    top = std::max(top, e[k]);
  }
  float sum = 0;
  for (int k = 0; k < kComponents; ++k) sum += (e[k] = std::exp(e[k] - top));
  if (responsibility)
    for (int k = 0; k < kComponents; ++k) responsibility[k] = e[k] / sum;
  return top + std::log(sum);
}

}  // namespace projtrack
