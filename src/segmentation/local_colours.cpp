#include "segmentation/local_colours.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

constexpr int kShift = 5;  // 256 / LocalColours::kLevels levels per bin
// Each class's pseudo-counts: its own count of pixels spread evenly over the bins, at this
// weight. A colour a cell has not seen is unlikely there, not impossible; and a colour both
// classes hold in the same share says nothing, however many more pixels one of them has in the
// cell (a pseudo-count of a fixed size made the class with more pixels win every colour the two
// share: a grey disc on a grey background of the same bin shrank by a fifth in ten frames).
constexpr float kPriorWeight = 1.0f;

int bin(const cv::Vec3b& c) {
  return ((c[0] >> kShift) * LocalColours::kLevels + (c[1] >> kShift)) * LocalColours::kLevels +
         (c[2] >> kShift);
}

// The cell of position `v` (work px) along a side of `length` px starting at `start`, cut into
// `cells`: the nearest one outside the box.
int cell_along(double v, double start, int length, int cells) {
  const double at = std::floor((v - start) * cells / length);
  return static_cast<int>(std::clamp(at, 0.0, static_cast<double>(cells - 1)));
}

}  // namespace

void LocalColours::learn(const cv::Mat& bgr, const cv::Rect& box, const cv::Mat& inside,
                         const cv::Mat& around, int cells) {
  cells_ = 0;
  if (box.empty() || cells < 1) return;
  const std::size_t n = static_cast<std::size_t>(cells) * cells;
  object_.assign(n * kBins, 0.f);
  surroundings_.assign(n * kBins, 0.f);
  object_total_.assign(n, 0.f);
  surroundings_total_.assign(n, 0.f);
  column_.resize(box.width);
  for (int x = 0; x < box.width; ++x) column_[x] = x * cells / box.width;
  for (int y = 0; y < box.height; ++y) {
    const cv::Vec3b* c = bgr.ptr<cv::Vec3b>(box.y + y) + box.x;
    const std::uint8_t* m = inside.ptr<std::uint8_t>(y);
    const std::uint8_t* a = around.ptr<std::uint8_t>(y);
    const int row = (y * cells / box.height) * cells;
    for (int x = 0; x < box.width; ++x) {
      const int cell = row + column_[x];
      if (m[x]) {
        object_[cell * kBins + bin(c[x])] += 1;
        object_total_[cell] += 1;
      } else if (a[x]) {
        surroundings_[cell * kBins + bin(c[x])] += 1;
        surroundings_total_[cell] += 1;
      }
    }
  }
  // One logarithm a colour a cell saw, not a pixel; a colour it did not see, or a cell that saw
  // one class only, tells nothing.
  ratio_.assign(n * kBins, 0.f);
  for (std::size_t cell = 0; cell < n; ++cell) {
    const float o = object_total_[cell], s = surroundings_total_[cell];
    if (o == 0 || s == 0) continue;
    const float po = kPriorWeight * o / kBins, ps = kPriorWeight * s / kBins;
    for (int b = 0; b < kBins; ++b) {
      const std::size_t i = cell * kBins + b;
      if (object_[i] == 0 && surroundings_[i] == 0) continue;
      const float r = std::log((object_[i] + po) * s / ((surroundings_[i] + ps) * o));
      ratio_[i] = std::clamp(r, -kMostNats, kMostNats);
    }
  }
  box_ = box;
  cells_ = cells;
}

void LocalColours::add_evidence(const cv::Mat& bgr, const cv::Rect& where, cv::Point2f moved,
                                double weight, cv::Mat& log_odds) {
  if (!learned() || weight <= 0) return;
  const auto w = static_cast<float>(weight);
  const double left = box_.x + moved.x, top = box_.y + moved.y;
  column_.resize(where.width);
  for (int x = 0; x < where.width; ++x)
    column_[x] = cell_along(where.x + x, left, box_.width, cells_);
  for (int y = 0; y < where.height; ++y) {
    const cv::Vec3b* c = bgr.ptr<cv::Vec3b>(where.y + y) + where.x;
    float* l = log_odds.ptr<float>(y);
    const float* row = ratio_.data() +
                       static_cast<std::size_t>(cell_along(where.y + y, top, box_.height, cells_)) *
                           cells_ * kBins;
    for (int x = 0; x < where.width; ++x) l[x] += w * row[column_[x] * kBins + bin(c[x])];
  }
}

void LocalColours::rescale(double rx, double ry) {
  const int x0 = static_cast<int>(std::lround(box_.x * rx));
  const int y0 = static_cast<int>(std::lround(box_.y * ry));
  box_ = cv::Rect(cv::Point(x0, y0),
                  cv::Point(std::max(x0 + 1, static_cast<int>(std::lround(box_.br().x * rx))),
                            std::max(y0 + 1, static_cast<int>(std::lround(box_.br().y * ry)))));
}

}  // namespace projtrack
