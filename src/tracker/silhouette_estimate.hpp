// The estimator on the object model's silhouette: the paper's methods measure the object's
// projection from its closed outline rather than from the frame's open edges.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/mask.hpp"
#include "core/work_scale.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/trace.hpp"
#include "projtrack/work_budget.hpp"
#include "tracker/silhouette_pieces.hpp"

namespace projtrack {

// The silhouette in work coordinates at `scale` (the object model's), in a width × height frame.
struct SilhouetteView {
  const Mask& mask;
  int scale = 1;
  int width = 0, height = 0;
};

// Buffers kept between frames, with no meaning after one.
struct SilhouetteEstimateBuffers {
  SilhouettePieces pieces;
  std::vector<std::uint8_t> barrier;  // one piece as an edge map
  Trace piece_trace;                  // a piece's trace, before it joins the frame's
};

// The estimate of `est` (method `m`) on silhouette `s`, from `inner` when it lies in the
// silhouette's largest piece (else from that piece's deepest point). Usually one estimate covers
// the silhouette; a fill that covers much less than its pixels (a neck or a finger kept it out)
// is redone piece by piece, and the pieces' features add up. Every estimate spends from
// `budget`. With a trace, it holds what the estimator did and the silhouette's outline.
Features estimate_on_silhouette(const SilhouetteView& s, const std::optional<Point2i>& inner,
                                Estimator& est, Method m, const Params& params, WorkBudget& budget,
                                SilhouetteEstimateBuffers& buffers, Trace* trace);

// The outline of `s` at full resolution within frame rectangle `r`: the pixels in it with a
// 4-neighbour out, into trace.outline (what the overlay draws).
void trace_outline(const SilhouetteView& s, const Rect& r, Trace& trace);

}  // namespace projtrack
