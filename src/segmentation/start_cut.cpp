#include "segmentation/start_cut.hpp"

#include <algorithm>
#include <cmath>

#include "segmentation/cut_pieces.hpp"
#include "segmentation/geodesic_evidence.hpp"
#include "segmentation/grid_cut.hpp"
#include "segmentation/mean_field.hpp"
#include "segmentation/start_work.hpp"

namespace projtrack {

namespace {

// The most one colour's evidence weighs, nats: a colour the surroundings never showed is not
// certain object.
constexpr float kMostColourEvidence = 10;

// The object's first weight of each colour bin less what the ring's colours would fill of the
// box's free cells (CutSettings::box_less_ring).
void subtract_ring(const CutProblem& pr, CutWorkspace& ws) {
  const ContrastField& f = ws.field;
  if (f.ring_bin.empty()) return;
  ws.ring_count.assign(f.bins(), 0.f);
  for (const int b : f.ring_bin) ws.ring_count[b] += 1.f;
  const auto per_sample = static_cast<float>(static_cast<double>(pr.free) / f.ring_bin.size());
  for (int b = 0; b < f.bins(); ++b)
    ws.object_weight[b] = std::max(0.f, ws.object_weight[b] - per_sample * ws.ring_count[b]);
}

// Each bin's share of the object (the labels' probabilities) and of the surroundings (the rest,
// and the ring's samples), then both mixtures fitted to them: two EM steps the first round (from
// the principal-axis split), one after (from the last round's).
void fit_colours(const CutProblem& pr, const std::vector<float>& q, bool first,
                 const CutSettings& s, CutWorkspace& ws) {
  const ContrastField& f = ws.field;
  ws.object_weight.assign(f.bins(), 0.f);
  ws.surroundings_weight.assign(f.bins(), 0.f);
  for (int i = 0; i < pr.cells(); ++i) {
    ws.object_weight[f.bin[i]] += q[i];
    ws.surroundings_weight[f.bin[i]] += 1 - q[i];
  }
  for (const int b : f.ring_bin) ws.surroundings_weight[b] += pr.ring_weight;
  if (first && s.box_less_ring) subtract_ring(pr, ws);
  ws.object.fit(f.colour, ws.object_weight, f.bin_spread, first, first ? 2 : 1);
  ws.surroundings.fit(f.colour, ws.surroundings_weight, f.bin_spread, first, first ? 2 : 1);
}

// Each cell's log-odds of the object: its colour's, its prior, and the geodesic evidence.
void weigh_cells(const CutProblem& pr, CutWorkspace& ws) {
  const ContrastField& f = ws.field;
  const bool both = ws.object.fitted() && ws.surroundings.fitted();
  ws.bin_odds.resize(f.bins());
  for (int b = 0; b < f.bins(); ++b)
    ws.bin_odds[b] = both ? std::clamp(ws.object.log_density(f.colour[b]) -
                                           ws.surroundings.log_density(f.colour[b]),
                                       -kMostColourEvidence, kMostColourEvidence)
                          : 0.f;
  ws.log_odds.resize(pr.cells());
  for (int i = 0; i < pr.cells(); ++i) ws.log_odds[i] = ws.bin_odds[f.bin[i]] + pr.prior[i];
  add_geodesic_evidence(pr, f, ws.log_odds, ws.to_object, ws.to_surroundings);
}

// The exact cut of the last round, when the budget leaves room for it beside the mean field's
// sweeps (what stands when it gives up). False when it gave up or did not run.
bool cut_exactly(const CutProblem& pr, CutWorkspace& ws, std::uint64_t fallback, WorkBudget& budget,
                 std::vector<float>& q) {
  const std::uint64_t n = pr.cells();
  if (!pay(budget, n * StartCosts::kCutBuild)) return false;
  build_cut_graph(pr, ws.field, ws.log_odds, ws.graph);
  const std::uint64_t arcs = ws.graph.arcs();
  // The cut may pass its cap by 3 × its nodes (BoundedMaxFlow::solve): kept out of what the
  // budget allows.
  const std::uint64_t spare = budget.left() > fallback ? budget.left() - fallback : 0;
  const std::uint64_t affordable = spare / StartCosts::kCutVisit;
  if (affordable <= 3 * n) return false;
  const auto cap =
      std::min(static_cast<std::uint64_t>(kCutVisitsPerArc * (arcs + n)), affordable - 3 * n);
  const bool done = cut_graph(ws.graph, cap, q);
  budget.spend(ws.graph.visits() * StartCosts::kCutVisit);
  return done;
}

}  // namespace

bool cut_object(const CutProblem& pr, const CutSettings& s, CutWorkspace& ws, WorkBudget& budget,
                CutResult& out) {
  const std::uint64_t n = pr.cells();
  if (!pay(budget, n * StartCosts::kField)) return false;
  make_field(pr, ws.field);
  std::vector<float>& q = out.probability;
  q.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    q[i] = pr.fixed[i] == CutProblem::kSurroundings ? 0.f
           : pr.fixed[i] == CutProblem::kObject     ? 1.f
                                                    : 1.f / (1.f + std::exp(-pr.prior[i]));
  const std::uint64_t bins = ws.field.bins();
  const std::uint64_t sweeps = n * s.sweeps * StartCosts::kMeanField;
  out.exact = false;
  for (int r = 0; r < s.rounds; ++r) {
    const std::uint64_t fit_steps = r == 0 ? 2 : 1;
    if (!pay(budget, n * StartCosts::kRound + bins * fit_steps * StartCosts::kFitBin)) return false;
    fit_colours(pr, q, r == 0, s, ws);
    weigh_cells(pr, ws);
    const bool last = r == s.rounds - 1;
    out.exact = s.exact && last && cut_exactly(pr, ws, sweeps, budget, q);
    if (out.exact) continue;
    if (!pay(budget, sweeps)) return false;
    mean_field(pr, ws.field, ws.log_odds, s.sweeps, q);
  }
  if (!pay(budget, n * StartCosts::kPieces)) return false;
  keep_pieces(pr, ws, out);
  score_outline(pr, ws.field, out);
  return true;
}

}  // namespace projtrack
