#include "segmentation/cut_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "segmentation/contrast_field.hpp"
#include "segmentation/start_work.hpp"

namespace projtrack {

namespace {

// Neighbouring pixels differing by ~4 grey levels a channel (3 × 4²) are noise and shading, not
// an outline: a flat white ellipse's middle measured 12-16, the squares around a small blurred
// ball 108-185 (its outline spread over pixels), textured scenes far more. A cell of s × s pixels
// averages the noise down to 1/s² of it; a cell smaller than a pixel (s < 1) is interpolated, and
// its neighbours differ by s² of what pixels do.
constexpr double kNoiseD2 = 48;

double noise_d2(const CutProblem& pr) {
  const double s2 = 1 / std::max(1e-6, pr.in.kx * pr.in.ky);  // a cell's area, frame px
  return kNoiseD2 * std::min(s2, 1 / s2);
}

// From a box, the pieces kept: at least this share of the largest (a limb the cut parted from the
// body stays, a speck of the object's colour in the corner does not).
constexpr double kLeastPiece = 0.1;

// `out`-sized rectangle the cut's grid covers.
cv::Rect covered(const CutProblem& pr, int width, int height, cv::Size out) {
  const double sx = static_cast<double>(out.width) / width;
  const double sy = static_cast<double>(out.height) / height;
  const cv::Rect& r = pr.in.rect;
  return cv::Rect(cv::Point(static_cast<int>(std::floor(r.x * sx)),
                            static_cast<int>(std::floor(r.y * sy))),
                  cv::Point(static_cast<int>(std::ceil(r.br().x * sx)),
                            static_cast<int>(std::ceil(r.br().y * sy)))) &
         cv::Rect({0, 0}, out);
}

}  // namespace

void keep_pieces(const CutProblem& pr, CutWorkspace& ws, CutResult& out) {
  const int n = pr.cells();
  cv::Mat object(pr.h, pr.w, CV_8U);
  for (int i = 0; i < n; ++i) object.data[i] = out.probability[i] > 0.5f ? 255 : 0;
  const int count =
      cv::connectedComponentsWithStats(object, ws.labels, ws.stats, ws.centroids, 8, CV_32S);
  int largest = 0;
  for (int l = 1; l < count; ++l)
    largest = std::max(largest, ws.stats.at<int>(l, cv::CC_STAT_AREA));
  const int* label = ws.labels.ptr<int>();
  const int clicked = pr.at >= 0 ? label[pr.at] : 0;
  out.kept.create(pr.h, pr.w, CV_8U);
  for (int i = 0; i < n; ++i) {
    const int l = label[i];
    const bool kept = pr.at >= 0
                          ? l == clicked && l > 0
                          : l > 0 && ws.stats.at<int>(l, cv::CC_STAT_AREA) >= kLeastPiece * largest;
    out.kept.data[i] = kept ? 255 : 0;
  }
}

void score_outline(const CutProblem& pr, const ContrastField& f, CutResult& out) {
  // Contrast is read against the grid's own mean difference (GrabCut's β), but no less than the
  // noise's: within a flat region (a white ellipse's middle) the mean is the sensor's noise, and
  // against it a noise blob's outline read as sharp as an object's.
  const double share = f.mean_d2 / std::max(f.mean_d2, noise_d2(pr));
  long edges = 0, touching = 0;
  double contrast = 0;
  for (int y = 0; y < pr.h; ++y)
    for (int x = 0; x < pr.w; ++x) {
      const int i = y * pr.w + x;
      if (!out.kept.data[i]) continue;
      for (int d = 0; d < 4; ++d) {
        const int u = x + kNeighbourDx[d], v = y + kNeighbourDy[d];
        const bool beyond = u < 0 || v < 0 || u >= pr.w || v >= pr.h;
        if (!beyond && out.kept.data[v * pr.w + u]) continue;
        ++edges;
        // The frame's edge counts as a sharp outline but as the box's edge too.
        if (beyond || pr.fixed[v * pr.w + u] == CutProblem::kSurroundings) ++touching;
        contrast += 1 - std::pow(f.weight[8 * i + d], share);
      }
    }
  out.contrast = edges ? contrast / edges : 0;
  out.touch = edges ? static_cast<double>(touching) / edges : 1;
}

std::uint64_t write_cost(const CutProblem& pr, int width, int height, cv::Size out_size) {
  const std::uint64_t inside = std::max(covered(pr, width, height, out_size).area(), 0);
  // The mask cleared, the grid upsampled into its part, and the whole read once more (a count).
  const std::uint64_t whole = static_cast<std::uint64_t>(out_size.area());
  return clearing_cost(out_size.width, out_size.height) + whole / kScannedPixelsPerCost +
         inside * StartCosts::kWrite + static_cast<std::uint64_t>(pr.cells()) * StartCosts::kWrite;
}

void write_cut(const CutProblem& pr, const CutResult& cut, int width, int height, cv::Size out_size,
               cv::Mat& mask) {
  mask.create(out_size, CV_8U);
  mask.setTo(0);
  const cv::Rect to = covered(pr, width, height, out_size);
  if (to.empty()) return;
  cv::Mat q = cv::Mat::zeros(pr.h, pr.w, CV_32F), up;
  cv::Mat(pr.h, pr.w, CV_32F, const_cast<float*>(cut.probability.data())).copyTo(q, cut.kept);
  cv::resize(q, up, to.size(), 0, 0, cv::INTER_LINEAR);
  mask(to).setTo(255, up > 0.5f);
}

}  // namespace projtrack
