// The mean field of a start's cut: each free cell's probability of being the object from its
// log-odds and its neighbours' probabilities under the contrast-weighted Potts model (a
// neighbour across low contrast pulls it to its own label) — what the cut's exact labels
// (grid_cut) are approximated by between the colour models' rounds.
#pragma once

#include <vector>

#include "segmentation/contrast_field.hpp"
#include "segmentation/cut_problem.hpp"

namespace projtrack {

// The Potts model's weight, nats per neighbour of the same colour (× its contrast weight): 5 of
// 1.5–50 measured best on davis-dev's first silhouettes (GrabCut's 50 over-smooths at a start's
// few thousand cells). The exact cut reads the same.
inline constexpr float kSmoothness = 5;

// `sweeps` sweeps over the free cells of `probability` (the object's, per cell), each sweep the
// other way round.
void mean_field(const CutProblem& problem, const ContrastField& field,
                const std::vector<float>& log_odds, int sweeps, std::vector<float>& probability);

}  // namespace projtrack
