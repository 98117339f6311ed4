#include "segmentation/grid_cut.hpp"

#include <algorithm>

#include "segmentation/mean_field.hpp"

namespace projtrack {

namespace {

// Capacities in units of 1/kPerNat nat: the same cut as on floats (davis-dev unchanged), without
// chains of vanishing float residues to push. A fixed cell's link can never be cut: kFixed nats.
constexpr float kPerNat = 64;
constexpr float kFixed = 1e6f;

BoundedMaxFlow::Capacity capacity(float nats) {
  return static_cast<BoundedMaxFlow::Capacity>(std::min(nats, kFixed) * kPerNat + 0.5f);
}

}  // namespace

void build_cut_graph(const CutProblem& pr, const ContrastField& f,
                     const std::vector<float>& log_odds, BoundedMaxFlow& graph) {
  const int n = pr.cells();
  graph.reset(n);
  for (int i = 0; i < n; ++i) {
    const std::uint8_t fixed = pr.fixed[i];
    const float object = fixed == CutProblem::kObject ? kFixed
                         : fixed == CutProblem::kFree ? std::max(log_odds[i], 0.f)
                                                      : 0.f;
    const float surroundings = fixed == CutProblem::kSurroundings ? kFixed
                               : fixed == CutProblem::kFree       ? std::max(-log_odds[i], 0.f)
                                                                  : 0.f;
    graph.add_terminals(i, capacity(object), capacity(surroundings));
  }
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 8; d += 2) {
      const float w = f.weight[8 * i + d];
      if (!(w > 0)) continue;
      const BoundedMaxFlow::Capacity c = capacity(kSmoothness * w);
      if (c > 0) graph.add_edge(i, i + kNeighbourDy[d] * pr.w + kNeighbourDx[d], c, c);
    }
}

bool cut_graph(BoundedMaxFlow& graph, std::uint64_t max_visits, std::vector<float>& q) {
  if (!graph.solve(max_visits)) return false;
  for (int i = 0; i < graph.nodes(); ++i) q[i] = graph.source_side(i) ? 1.f : 0.f;
  return true;
}

}  // namespace projtrack
