// A start's cut of one hypothesis (cut_problem): GrabCut's loop at a fixed size — colour models of
// the object and of its surroundings learned from the current labels, then the labels from the
// colours, the prior, the geodesic evidence and the contrast — for a fixed number of rounds, the
// last by an exact cut when asked for and when it fits. Every stage pays the frame's budget
// before it runs (start_work.hpp): a cut stops between stages when the budget cannot pay or the
// stop flag is set.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "projtrack/work_budget.hpp"
#include "segmentation/bounded_max_flow.hpp"
#include "segmentation/contrast_field.hpp"
#include "segmentation/cut_problem.hpp"
#include "segmentation/gaussian_mixture.hpp"

namespace projtrack {

struct CutSettings {
  int rounds = 2;
  bool exact = true;  // the last round by max-flow (else by mean field)
  int sweeps = 2;     // mean-field sweeps a round
  // The hypothesis is a box drawn around the object, holding the object and some of what
  // surrounds it: the object's first colours are the box's less its surroundings' (the ring's,
  // as many as the box holds cells), so that a colour as common around the box as in it says
  // nothing of the object. (A click's square is no such box: it may hold only a part of the
  // object, or mostly its surroundings.)
  bool box_less_ring = false;
};

struct CutResult {
  std::vector<float> probability;  // the object's, per cell (0 or 1 where the exact cut ran)
  cv::Mat kept;                    // CV_8U, the grid's size: 255 on the pieces kept
  // Along the kept pieces' outline: the mean contrast (1 - the contrast weight) and the share of
  // it on the box's edge (where the hypothesis cut, not the picture).
  double contrast = 0, touch = 1;
  bool exact = false;  // the max-flow finished
};

// What a cut's stages keep from one to the next, and from one cut to the next.
struct CutWorkspace {
  ContrastField field;
  GaussianMixture object, surroundings;
  std::vector<float> log_odds, object_weight, surroundings_weight, ring_count, bin_odds, to_object,
      to_surroundings;
  BoundedMaxFlow graph;
  cv::Mat labels, stats, centroids;
};

// The cut of `problem` into `out`; false when the budget could not pay for it or the stop flag
// was set (`out` then holds nothing usable).
bool cut_object(const CutProblem& problem, const CutSettings& settings, CutWorkspace& ws,
                WorkBudget& budget, CutResult& out);

}  // namespace projtrack
