// What a start's cut reads of its grid's picture: each cell's colour bin (the colour models are
// fitted to the bins' mean colours, not to the cells: a fit's cost is bounded by the bins), and
// between each cell and its 8 neighbours the contrast, as a smoothness weight exp(-β d²) (β
// from the mean squared difference around: GrabCut's) and as a geodesic step length.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "segmentation/cut_problem.hpp"

namespace projtrack {

// The 8 neighbours' offsets: right, left, down, up, then the diagonals; neighbour d's reverse is
// d ^ 1.
inline constexpr int kNeighbourDx[8] = {1, -1, 0, 0, 1, -1, -1, 1};
inline constexpr int kNeighbourDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

struct ContrastField {
  std::vector<int> bin;           // per cell
  std::vector<int> ring_bin;      // per surroundings sample
  std::vector<cv::Vec3f> colour;  // per bin: the mean colour of its cells and samples
  cv::Vec3f bin_spread;           // a bin's own variance a channel (grey levels²)
  double mean_d2 = 1;             // the weights' scale: the mean squared difference around
  std::vector<float> weight;      // 8 per cell: exp(-β d²), √½ that on a diagonal; 0: none
  std::vector<float> step;        // 8 per cell: the geodesic length of the step

  int bins() const { return static_cast<int>(colour.size()); }
};

// The field of `problem`'s grid, into `out` (its buffers reused).
void make_field(const CutProblem& problem, ContrastField& out);

}  // namespace projtrack
