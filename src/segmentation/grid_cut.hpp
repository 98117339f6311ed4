// The exact labels of a start's cut: the minimum cut of the contrast-weighted Potts model on the
// cut's grid (8-connected, as the mean field reads it), by max-flow on integer capacities. Where
// the mean field is confident but wrong the cut fixes it (davis-dev's first silhouettes from the
// box: mean field alone 0.45–0.57, with the cut 0.60; cutting only the band where the mean field
// is unsure 0.48).
#pragma once

#include <cstdint>
#include <vector>

#include "segmentation/bounded_max_flow.hpp"
#include "segmentation/contrast_field.hpp"
#include "segmentation/cut_problem.hpp"

namespace projtrack {

// The arc visits per arc and node of the graph past which the cut gives up (the mean field's
// labels then stand): the exact cuts of davis-dev's and the real clips' first frames (their boxes
// and clicks) took 12.1 at most, most under 8; uniform noise reaches it, and costs about 3.5M
// work units a cut of 4000 cells then.
inline constexpr double kCutVisitsPerArc = 16;

// The graph of `problem`'s cut with `log_odds` (per cell) into `graph`; its arcs and nodes.
void build_cut_graph(const CutProblem& problem, const ContrastField& field,
                     const std::vector<float>& log_odds, BoundedMaxFlow& graph);
// The cut of the graph built, within `max_visits` arc visits: `probability` (per cell) 1 on the
// object's side, 0 on the other. False (`probability` untouched) when it gave up.
bool cut_graph(BoundedMaxFlow& graph, std::uint64_t max_visits, std::vector<float>& probability);

}  // namespace projtrack
