#include "segmentation/contrast_field.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

// A step across one rms colour difference is as long as kGamma steps across a flat region
// (geodesic evidence, segmentation/geodesic_evidence).
constexpr double kGamma = 3;

// The most colour bins at ColourBins::kLevels a channel: real footage's boxes fill 16 to 632 of
// them (davis-dev and the real clips' first frames) from about 7000 samples, noise nearly one a
// sample; past this the colours are binned at half as many levels (at most 512 bins), so that
// the colour models' fit, whose work is the bins', stays bounded.
constexpr int kMostBins = 1024;

// The bins of the cells and the ring's samples at kLevels >> `coarser` levels a channel; false
// when they are more than `most`.
bool bin_colours(const CutProblem& pr, int coarser, int most, ContrastField& f) {
  const int levels = ColourBins::kLevels >> coarser;
  std::vector<int> id(levels * levels * levels, -1);
  std::vector<cv::Vec3d> sum;
  std::vector<double> count;
  const auto bin_of = [&](const cv::Vec3b& c, double weight) {
    int& b = id[pr.bins.index(c, coarser)];
    if (b < 0) {
      b = static_cast<int>(sum.size());
      sum.emplace_back(0, 0, 0);
      count.push_back(0);
    }
    sum[b] += weight * cv::Vec3d(c[0], c[1], c[2]);
    count[b] += weight;
    return b;
  };
  const cv::Vec3b* px = pr.in.bgr.ptr<cv::Vec3b>();
  f.bin.resize(pr.cells());
  for (int i = 0; i < pr.cells(); ++i) f.bin[i] = bin_of(px[i], 1);
  f.ring_bin.clear();
  for (const cv::Vec3b& c : pr.ring) f.ring_bin.push_back(bin_of(c, pr.ring_weight));
  if (static_cast<int>(sum.size()) > most) return false;
  f.colour.clear();
  for (std::size_t b = 0; b < sum.size(); ++b) f.colour.emplace_back(sum[b] / count[b]);
  // A bin's colours lie near its mean: a third of a uniform bin's variance (w² / 12).
  for (int k = 0; k < 3; ++k) {
    const float width = pr.bins.width[k] * static_cast<float>(1 << coarser);
    f.bin_spread[k] = width * width / 32;
  }
  return true;
}

}  // namespace

void make_field(const CutProblem& pr, ContrastField& f) {
  if (!bin_colours(pr, 0, kMostBins, f)) bin_colours(pr, 1, kMostBins, f);
  const int n = pr.cells();
  const cv::Vec3b* px = pr.in.bgr.ptr<cv::Vec3b>();
  f.weight.assign(8 * static_cast<std::size_t>(n), 0.f);
  f.step.assign(8 * static_cast<std::size_t>(n), 0.f);
  // Each pair once, from the cell before it: its squared difference first.
  double total = pr.around_d2;
  long pairs = pr.around_pairs;
  for (int y = 0; y < pr.h; ++y)
    for (int x = 0; x < pr.w; ++x)
      for (int d = 0; d < 8; d += 2) {
        const int u = x + kNeighbourDx[d], v = y + kNeighbourDy[d];
        if (u < 0 || v < 0 || u >= pr.w || v >= pr.h) continue;
        const cv::Vec3i a = px[y * pr.w + x], b = px[v * pr.w + u];
        const auto d2 = static_cast<float>((a - b).dot(a - b));
        f.weight[8 * (y * pr.w + x) + d] = d2;
        total += d2;
        ++pairs;
      }
  const double mean_d2 = std::max(1e-6, pairs ? total / pairs : 0);
  f.mean_d2 = mean_d2;
  for (int y = 0; y < pr.h; ++y)
    for (int x = 0; x < pr.w; ++x)
      for (int d = 0; d < 8; d += 2) {
        const int u = x + kNeighbourDx[d], v = y + kNeighbourDy[d];
        if (u < 0 || v < 0 || u >= pr.w || v >= pr.h) continue;
        const int i = y * pr.w + x, j = v * pr.w + u;
        const float d2 = f.weight[8 * i + d];
        const bool diagonal = d >= 4;
        const auto weight =
            static_cast<float>(std::exp(-d2 / (2 * mean_d2)) * (diagonal ? std::sqrt(0.5) : 1.0));
        const auto length =
            static_cast<float>(std::sqrt((diagonal ? 2.0 : 1.0) + kGamma * kGamma * d2 / mean_d2));
        // A neighbour's weight is never 0: 0 says "no neighbour".
        f.weight[8 * i + d] = f.weight[8 * j + (d ^ 1)] = std::max(weight, 1e-30f);
        f.step[8 * i + d] = f.step[8 * j + (d ^ 1)] = length;
      }
}

}  // namespace projtrack
