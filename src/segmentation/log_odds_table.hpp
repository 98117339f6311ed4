// A probability's log-odds by table: the prior's logarithm is taken for every work pixel of every
// frame, and a table of 4 096 steps is within 0.01 nats of std::log where it matters.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace projtrack {

class LogOddsTable {
 public:
  static constexpr int kSteps = 4096;

  // The table for probabilities kept within [floor, 1 - floor]; kept when `floor` is unchanged.
  void build(double floor) {
    if (floor == floor_) return;
    floor_ = floor;
    const double lo = floor, hi = 1 - floor;
    for (int i = 0; i <= kSteps; ++i) {
      const double q = std::clamp(static_cast<double>(i) / kSteps, lo, hi);
      table_[i] = static_cast<float>(std::log(q / (1 - q)));
    }
  }
  // The log-odds of `q`, read as the nearest step (q above 1 as 1; below 0, or NaN, as 0).
  float operator()(float q) const {
    const float i = (q > 0 ? std::min(q, 1.0f) : 0.0f) * kSteps + 0.5f;
    return table_[static_cast<int>(i)];
  }

 private:
  double floor_ = -1;
  std::array<float, kSteps + 1> table_{};
};

}  // namespace projtrack
