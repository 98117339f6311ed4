// What projtrack-bench's parts share: the run's options and the constants its CSVs and meta.json
// are judged by.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "projtrack/tracker.hpp"

namespace projtrack::bench {

inline constexpr double kLeakFactor = 1.5;  // an estimate above 1.5× the true area leaked
// Auto acquisition's strategies, by the names the report uses.
inline const std::pair<const char*, AutoAcquisition> kStrategies[] = {
    {"motion-centroid", AutoAcquisition::MotionCentroid},
    {"compact-moving-region", AutoAcquisition::CompactMovingRegion}};
inline constexpr int kAcquisitionFrames = 30;

struct Options {
  bool quick = false;
  std::string out = "docs/benchmarks";
  int seeds = 24;
  int reps = 3;
  std::string command;
};

}  // namespace projtrack::bench
