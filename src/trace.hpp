// An optional record of what an estimator did, for overlays and the paper's figures.
#pragma once

#include <vector>

#include "geometry.hpp"

namespace projtrack {

// Pass a Trace to Estimator::estimate() to get it filled; pass none and nothing is recorded.
// The vectors keep their capacity across frames, so a reused Trace does not allocate per frame.
struct Trace {
  struct Ray {
    Point2d origin;
    Point2d hit;    // where it met an edge or the frame border
    int iteration;  // 1-based; 0 for the final inner-point update
    int level;      // 1 for rays from the inner point, 2.. for recast rays (n^y methods)
  };
  struct Block {
    Rect rect;      // an m×m block selected by rasterization (clipped to the frame)
    int iteration;  // when it was first selected
  };
  struct Run {
    Point2i first;  // a horizontal or vertical run of filled pixels, both ends included
    Point2i last;
  };
  struct Iteration {
    Point2i inner_point;  // where this iteration cast from
    Point2d centroid;
    double area;  // px², when the method estimates one per iteration (else 0)
  };

  std::vector<Ray> rays;
  std::vector<Block> blocks;
  std::vector<Run> runs;  // pixel-filling: row runs; grid-filling: grid-line runs
  std::vector<Iteration> iterations;

  void clear() {
    rays.clear();
    blocks.clear();
    runs.clear();
    iterations.clear();
  }
};

}  // namespace projtrack
