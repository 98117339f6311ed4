// What the starts' stages cost, in the frame budget's units (work_budget.hpp), and how they pay:
// before each stage, for what it is about to do, so that a start stops between stages when the
// frame cannot pay or the stop flag is set, and never passes its budget.
//
// Measured against the tracked frames' units: the starts on davis-dev's and the real clips' first
// frames, each stage timed beside the tracker's frames in the same run (bench/starts/unit_cost.py
// in the commit that set them), so that a unit of a start costs what a unit of a tracked frame
// costs.
#pragma once

#include <cstdint>

#include "projtrack/work_budget.hpp"

namespace projtrack {

struct StartCosts {
  static constexpr std::uint64_t kRead = 11;       // a patch pixel: 4 samples of 3 planes
  static constexpr std::uint64_t kProblem = 6;     // a cell's labels and prior, a sample's contrast
  static constexpr std::uint64_t kField = 38;      // a cell's bin, 4 contrasts and steps
  static constexpr std::uint64_t kRound = 24;      // a cell's evidence and geodesic sweeps
  static constexpr std::uint64_t kMeanField = 12;  // a cell's mean-field update, per sweep
  static constexpr std::uint64_t kFitBin = 110;    // a colour bin's share of an EM step
  static constexpr std::uint64_t kCutVisit = 6;    // an arc visit of the max-flow
  static constexpr std::uint64_t kCutBuild = 22;   // a cell's node and arcs
  static constexpr std::uint64_t kPieces = 10;     // a cell's labels, pieces and outline
  static constexpr std::uint64_t kWrite = 2;       // an output pixel of the mask, a cell read
};

// Takes `units` from `budget`; false, taking nothing, when they do not fit or the stop flag is
// set.
inline bool pay(WorkBudget& budget, std::uint64_t units) {
  if (budget.exhausted(units)) return false;
  budget.spend(units);
  return true;
}

}  // namespace projtrack
