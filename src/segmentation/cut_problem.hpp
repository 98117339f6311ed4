// One cut of a start: a rectangle of the frame that holds the object (a user's box, or a square
// around a click) on a grid of about a given number of cells, what is known of each cell (fixed
// as surroundings beyond the rectangle, fixed as object at a click, a prior within), and a sample
// of the surroundings' colours around it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projtrack/color_view.hpp"
#include "projtrack/geometry.hpp"
#include "segmentation/start_patch.hpp"

namespace projtrack {

// Where the object is thought to be.
struct CutHypothesis {
  cv::Rect box;                    // frame px: the object lies within it
  const Point2i* point = nullptr;  // a click: certain object around it
  double pixels = 4000;            // the box's cells
  double context = 0.5;            // the surroundings sampled: the box grown by this share a side
  cv::Point2d centre;              // the object expected in this ellipse (frame px)
  cv::Size2d radii;
};

// The colour bins of a cut: each channel's 16 bins span what the box and its surroundings show of
// it (its 0.5th to 99.5th percentile, at least 32 grey levels: two a bin), so that an object a
// dozen grey levels off a grey wall falls in bins of its own, as on a colourful picture.
struct ColourBins {
  static constexpr int kLevels = 16;
  float lo[3] = {0, 0, 0};
  float width[3] = {16, 16, 16};  // grey levels a bin

  // The bin of `c` at kLevels >> `coarser` levels a channel.
  int index(const cv::Vec3b& c, int coarser = 0) const {
    const int levels = kLevels >> coarser;
    int i = 0;
    for (int k = 0; k < 3; ++k) {
      const int l = static_cast<int>((c[k] - lo[k]) / width[k]);
      i = i * levels + (std::min(std::max(l, 0), kLevels - 1) >> coarser);
    }
    return i;
  }
};

struct CutProblem {
  enum Fixed : std::uint8_t { kFree, kSurroundings, kObject };
  Patch in;  // the box grown by a cell of surroundings where the frame goes on
  int w = 0, h = 0;
  std::vector<std::uint8_t> fixed;  // per cell, Fixed
  std::vector<float> prior;         // per cell, the object's log-odds
  std::vector<cv::Vec3b> ring;      // the surroundings' colours, the box left out
  float ring_weight = 1;            // a ring sample's area in cells
  // The sum of squared colour differences of neighbours around the box and their count: the
  // scale of the picture's contrast, with the box's own.
  double around_d2 = 0;
  long around_pairs = 0;
  ColourBins bins;
  int at = -1;   // the click's cell, or -1
  int free = 0;  // cells not fixed

  int cells() const { return w * h; }
};

// What reading `hypothesis` on a width × height frame costs, work units.
std::uint64_t problem_cost(const CutHypothesis& hypothesis, int width, int height);
// `hypothesis` read from `frame` into `out`.
void make_problem(const ColorView& frame, const CutHypothesis& hypothesis, CutProblem& out);

// Why there is nothing to cut, or empty: a picture with no contrast (its largest channel's
// standard deviation over the box and its surroundings under 1.5 grey levels, the frame's own
// quantum of colour), or a box whose colours are its surroundings' (their 8³ histograms overlap
// with a Bhattacharyya coefficient above 0.97: noise everywhere).
std::string nothing_to_cut(const CutProblem& problem);

}  // namespace projtrack
