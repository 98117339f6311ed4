// The estimators' parameters and a caller's options for one estimate, their defaults and their
// valid ranges.
#pragma once

#include <string>

namespace projtrack {

// Defaults chosen by the benchmark (docs/benchmarks.md, "Defaults, chosen by the numbers"): on
// scenes with and without edge gaps, the lowest error, and the cheaper value where errors tie.
// The paper's figures used n = 32, 16^2, 8-rasterization and 8-grids; the original system
// iterated until the inner point moved < 2 px, at most 10 times.
struct Params {
  int rays = 8;              // n: rays per cast, evenly spread in angle          [3, 1024]
  int recursion = 2;         // y: levels of re-casting from hit points (n^y)     [1, 4]
  int block_size = 4;        // m of m-rasterization, px                          [1, 65536]
  int grid_size = 16;        // m of m-grid-filling, px                           [1, 65536]
  int max_iterations = 3;    // cap for the iterative methods                     [1, 1000]
  double convergence = 4.0;  // stop iterating when inner point and centroid move less, px [0, 1e6]
  int seed_radius = 4;       // how far to look for a free pixel around the inner point, px [0, 64]
  int max_gap = 12;  // gap-tolerant filling: longest contour gap it will not cross, px [1, 15]
};

class WorkBudget;

// What the caller of one estimate (a tracker) sets for that call alone, beside the estimator's
// parameters (Params: the user's settings): how far a fill may go, what kind of edge map it is
// given, and the work it may do. Estimator::estimate takes them as their own argument.
struct EstimateOptions {
  // The fills (pixel-, grid- and gap-tolerant filling) stop once their area passes this, px² (0 =
  // never). A tracker sets it just above what it would refuse anyway, so a leak costs about the
  // object's size instead of the frame's. A stopped estimate has area > area_limit, and its
  // centroid and box cover only what was filled.                                     [0, 1e12]
  double area_limit = 0;
  // The edge map is a closed outline (every pixel off the object is an edge: a silhouette's), so
  // there is no leak to stop and no gap to tolerate: gap-tolerant filling is then grid filling
  // (a narrow neck of the object is no break in its contour), at grid filling's cost.
  bool closed_outline = false;
  // The work the estimate may do, and the flag that stops it (work_budget.hpp): it spends what
  // it does from this budget, shared with whatever else the caller spends it on (a tracker's
  // frame: every seed, region and piece). Null: unlimited.
  WorkBudget* budget = nullptr;
};

inline constexpr int kMinRays = 3, kMaxRays = 1024;
inline constexpr int kMinRecursion = 1, kMaxRecursion = 4;
inline constexpr int kMaxCellSize = 65536;
inline constexpr int kMaxIterations = 1000;
inline constexpr double kMaxConvergence = 1e6;
inline constexpr int kMaxSeedRadius = 64;
inline constexpr double kMaxAreaLimit = 1e12;
inline constexpr int kMaxGap = 15;
// n^y is capped so one cast stays bounded: 1024^1, 1024^2 = 1M ... are refused above this.
inline constexpr long long kMaxRaysPerCast = 1 << 20;

// Empty when every parameter (option) is in range; otherwise says which one is not, and why.
std::string validate(const Params& p);
std::string validate(const EstimateOptions& o);

// The paper's values (its figures: 32 rays, 16^2 recursion, 8-rasterization, an 8-grid) with the
// original system's iteration rule (< 2 px, at most 10 iterations): for reproducing the paper.
Params paper_params();

}  // namespace projtrack
