#include "segmentation/cut_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "segmentation/start_work.hpp"

namespace projtrack {

namespace {

// Within a box the object is expected in the hypothesis' ellipse: log-odds kPrior at its centre,
// 0 on it and below it beyond (a box's corners).
constexpr double kPrior = 1;
// A click's certain disc: this share of the ellipse's smaller radius (with only the click's cell
// certain, the object's first colours are the ellipse's, mostly the surroundings' on a thin
// object).
constexpr double kCertain = 0.15;
// No contrast (nothing_to_cut): the largest channel's standard deviation under kFlat grey
// levels, or the box's colours its surroundings' (histogram overlap above kSame).
constexpr double kFlat = 1.5, kSame = 0.97;
// The colour bins' span: the middle 99 % of each channel's values, at least this many grey levels.
constexpr double kTail = 0.005;
constexpr float kLeastSpan = 32;

cv::Rect frame_rect(int width, int height) { return {0, 0, width, height}; }

// The box grown by one cell (at `pixels` cells in the box) a side, within the frame: those
// cells are fixed surroundings.
cv::Rect grown_box(const CutHypothesis& h, int width, int height) {
  const cv::Rect& b = h.box;
  const int m = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(b.area()) / h.pixels)));
  return cv::Rect(b.x - m, b.y - m, b.width + 2 * m, b.height + 2 * m) & frame_rect(width, height);
}

double grown_pixels(const CutHypothesis& h, const cv::Rect& grown) {
  return h.pixels * grown.area() / std::max(1, h.box.area());
}

// The surroundings sampled: the box grown by `context` of its sides, within the frame.
cv::Rect around_box(const CutHypothesis& h, int width, int height) {
  const cv::Rect& b = h.box;
  const int gx = static_cast<int>(std::lround(h.context * b.width));
  const int gy = static_cast<int>(std::lround(h.context * b.height));
  return cv::Rect(b.x - gx, b.y - gy, b.width + 2 * gx, b.height + 2 * gy) &
         frame_rect(width, height);
}

void label_cells(const CutHypothesis& hyp, CutProblem& pr) {
  const cv::Rect& grown = pr.in.rect;
  const double ax = hyp.radii.width, ay = hyp.radii.height;
  const double certain = kCertain * std::min(ax * pr.in.kx, ay * pr.in.ky);  // cells
  const double certain2 = std::max(0.49, certain * certain);
  for (int y = 0; y < pr.h; ++y)
    for (int x = 0; x < pr.w; ++x) {
      const double fx = grown.x + (x + 0.5) / pr.in.kx, fy = grown.y + (y + 0.5) / pr.in.ky;
      const int i = y * pr.w + x;
      if (!hyp.box.contains(cv::Point(static_cast<int>(fx), static_cast<int>(fy)))) {
        pr.fixed[i] = CutProblem::kSurroundings;
        continue;
      }
      const double ex = (fx - hyp.centre.x) / ax, ey = (fy - hyp.centre.y) / ay;
      pr.prior[i] = static_cast<float>(kPrior * (1 - std::sqrt(ex * ex + ey * ey)));
      if (!hyp.point) continue;
      const double px = (fx - hyp.point->x - 0.5) * pr.in.kx;
      const double py = (fy - hyp.point->y - 0.5) * pr.in.ky;
      if (px * px + py * py <= certain2) pr.fixed[i] = CutProblem::kObject;
    }
  if (hyp.point) {
    const int x =
        std::clamp(static_cast<int>((hyp.point->x + 0.5 - grown.x) * pr.in.kx), 0, pr.w - 1);
    const int y =
        std::clamp(static_cast<int>((hyp.point->y + 0.5 - grown.y) * pr.in.ky), 0, pr.h - 1);
    pr.at = y * pr.w + x;
    pr.fixed[pr.at] = CutProblem::kObject;
  }
  pr.free = static_cast<int>(std::count(pr.fixed.begin(), pr.fixed.end(), CutProblem::kFree));
}

// The surroundings' colours (`around` outside the box) and the contrast of all of `around`.
void sample_surroundings(const Patch& around, const cv::Rect& box, CutProblem& pr) {
  pr.ring.clear();
  for (int y = 0; y < around.bgr.rows; ++y)
    for (int x = 0; x < around.bgr.cols; ++x) {
      const cv::Point f(around.rect.x + static_cast<int>((x + 0.5) / around.kx),
                        around.rect.y + static_cast<int>((y + 0.5) / around.ky));
      if (!box.contains(f)) pr.ring.push_back(around.bgr.at<cv::Vec3b>(y, x));
    }
  pr.ring_weight = static_cast<float>(pr.in.kx * pr.in.ky / (around.kx * around.ky));
  pr.around_d2 = 0;
  pr.around_pairs = 0;
  for (int y = 0; y + 1 < around.bgr.rows; ++y)
    for (int x = 0; x + 1 < around.bgr.cols; ++x) {
      const cv::Vec3i a = around.bgr.at<cv::Vec3b>(y, x);
      const cv::Vec3i r = around.bgr.at<cv::Vec3b>(y, x + 1);
      const cv::Vec3i d = around.bgr.at<cv::Vec3b>(y + 1, x);
      pr.around_d2 += (a - r).dot(a - r) + (a - d).dot(a - d);
      pr.around_pairs += 2;
    }
}

// Each channel's bins (ColourBins) from the cells and the ring's samples.
void scale_bins(CutProblem& pr) {
  int count[3][256] = {};
  const cv::Vec3b* px = pr.in.bgr.ptr<cv::Vec3b>();
  for (int i = 0; i < pr.cells(); ++i)
    for (int k = 0; k < 3; ++k) ++count[k][px[i][k]];
  for (const cv::Vec3b& c : pr.ring)
    for (int k = 0; k < 3; ++k) ++count[k][c[k]];
  const double n = pr.cells() + static_cast<double>(pr.ring.size());
  for (int k = 0; k < 3; ++k) {
    int lo = 0, hi = 255;
    for (double below = 0; lo < 255 && (below += count[k][lo]) <= kTail * n;) ++lo;
    for (double above = 0; hi > 0 && (above += count[k][hi]) <= kTail * n;) --hi;
    const float span = std::max(kLeastSpan, static_cast<float>(hi - lo + 1));
    const float middle = (lo + hi + 1) / 2.f;
    pr.bins.lo[k] = middle - span / 2;
    pr.bins.width[k] = span / ColourBins::kLevels;
  }
}

}  // namespace

std::uint64_t problem_cost(const CutHypothesis& h, int width, int height) {
  const cv::Rect grown = grown_box(h, width, height);
  const std::uint64_t cells = patch_size(grown, grown_pixels(h, grown)).area();
  const std::uint64_t around = patch_size(around_box(h, width, height), h.pixels).area();
  return (cells + around) * (StartCosts::kRead + StartCosts::kProblem);
}

void make_problem(const ColorView& frame, const CutHypothesis& hyp, CutProblem& pr) {
  const int width = frame.luma.width, height = frame.luma.height;
  const cv::Rect grown = grown_box(hyp, width, height);
  read_patch(frame, grown, grown_pixels(hyp, grown), pr.in);
  pr.w = pr.in.bgr.cols;
  pr.h = pr.in.bgr.rows;
  pr.fixed.assign(pr.cells(), CutProblem::kFree);
  pr.prior.assign(pr.cells(), 0.f);
  pr.at = -1;
  label_cells(hyp, pr);
  Patch around;
  read_patch(frame, around_box(hyp, width, height), hyp.pixels, around);
  sample_surroundings(around, hyp.box, pr);
  scale_bins(pr);
}

std::string nothing_to_cut(const CutProblem& pr) {
  double s[3] = {0, 0, 0}, s2[3] = {0, 0, 0};
  constexpr int kBins = 512;  // 8 levels a channel
  std::vector<double> in_box(kBins, 0), ring(kBins, 0);
  const auto add = [&](const cv::Vec3b& c, std::vector<double>& histogram, double weight) {
    for (int k = 0; k < 3; ++k) s[k] += weight * c[k], s2[k] += weight * c[k] * c[k];
    histogram[pr.bins.index(c, 1)] += weight;
  };
  double n_box = 0;
  const cv::Vec3b* px = pr.in.bgr.ptr<cv::Vec3b>();
  for (int i = 0; i < pr.cells(); ++i)
    if (pr.fixed[i] != CutProblem::kSurroundings) add(px[i], in_box, 1), n_box += 1;
  for (const cv::Vec3b& c : pr.ring) add(c, ring, pr.ring_weight);
  const double n_ring = pr.ring_weight * static_cast<double>(pr.ring.size());
  const double n = n_box + n_ring;
  double variance = 0;
  for (int k = 0; k < 3; ++k) variance = std::max(variance, s2[k] / n - (s[k] / n) * (s[k] / n));
  if (const double spread = std::sqrt(std::max(0.0, variance)); spread < kFlat) {
    char why[120];
    std::snprintf(why, sizeof why,
                  "nothing to cut: the picture there is one colour (its channels vary by %.2g "
                  "grey levels at most)",
                  spread);
    return why;
  }
  if (pr.ring.empty() || n_box == 0) return {};
  double overlap = 0;
  for (int b = 0; b < kBins; ++b) overlap += std::sqrt(in_box[b] / n_box * ring[b] / n_ring);
  if (overlap > kSame)
    return "nothing to cut: the colours within are those around it (the same noise everywhere)";
  return {};
}

}  // namespace projtrack
