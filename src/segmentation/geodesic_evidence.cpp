#include "segmentation/geodesic_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace projtrack {

namespace {

// A cell's colour evidence makes it a seed at up to kReach × √(free cells) steps (a share of the
// box's side); the evidence added is at most kMost nats.
constexpr double kReach = 0.5;
constexpr float kMost = 2;

}  // namespace

void add_geodesic_evidence(const CutProblem& pr, const ContrastField& f,
                           std::vector<float>& log_odds, std::vector<float>& to_object,
                           std::vector<float>& to_surroundings) {
  const int n = pr.cells();
  const auto reach =
      static_cast<float>(kReach * std::sqrt(static_cast<double>(std::max(1, pr.free))));
  const float far = std::numeric_limits<float>::max() / 4;
  to_object.resize(n);
  to_surroundings.resize(n);
  for (int i = 0; i < n; ++i) {
    const float p = 1.f / (1.f + std::exp(-log_odds[i]));
    const std::uint8_t fixed = pr.fixed[i];
    to_object[i] = fixed == CutProblem::kSurroundings ? far
                   : fixed == CutProblem::kObject     ? 0.f
                                                      : reach * (1 - p);
    to_surroundings[i] = fixed == CutProblem::kObject         ? far
                         : fixed == CutProblem::kSurroundings ? 0.f
                                                              : reach * p;
  }
  // The neighbours a sweep has passed already: forwards the left, up and the two upper
  // diagonals; backwards their reverses.
  const int before[2][4] = {{1, 3, 5, 7}, {0, 2, 4, 6}};
  for (int way = 0; way < 2; ++way)
    for (int k = 0; k < n; ++k) {
      const int i = way ? n - 1 - k : k;
      for (const int d : before[way]) {
        const float length = f.step[8 * i + d];
        if (length <= 0) continue;
        const int j = i + kNeighbourDy[d] * pr.w + kNeighbourDx[d];
        to_object[i] = std::min(to_object[i], to_object[j] + length);
        to_surroundings[i] = std::min(to_surroundings[i], to_surroundings[j] + length);
      }
    }
  for (int i = 0; i < n; ++i)
    log_odds[i] += kMost * std::clamp((to_surroundings[i] - to_object[i]) / reach, -1.f, 1.f);
}

}  // namespace projtrack
