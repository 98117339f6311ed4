// The edges model's estimate on the edges around the object only: a region predicted from the
// last box and its motion, grown until it no longer cuts the estimate.
#pragma once

#include "edges/edge_source.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

// The least margin around the object's box, px (TrackerParams::edge_margin).
inline constexpr int kLeastEdgeMargin = 16;

// The region the edges are first computed in for the estimate of method `m` around an object
// whose last accepted box is `last`, moving by `velocity` (px a frame), in a width × height
// frame: `last` and `last` moved by `velocity`, grown by TrackerParams::edge_margin of the box's
// larger side (at least kLeastEdgeMargin px), and by max_gap + 2 px more for a method that reads
// max_gap (the band it reads beside its lines, kReadsMaxGap); clipped to the frame and anchored
// on the block grid (so that rasterized ray-casting's blocks line up with the frame's). Needs
// TrackerParams::edge_margin >= 0.
Rect edge_region(const Rect& last, Point2d velocity, Method m, const Params& params,
                 const TrackerParams& tp, int width, int height);

// The estimate of `est` (method `m`) from `inner` on the edges of `edges`: in edge_region() when
// there is a last box, TrackerParams::edge_margin >= 0 and the region holds the inner point; else
// on the whole frame. An estimate that reaches the region's border (where it is not the frame's)
// is redone on a larger region, then on the whole frame, so that the answer does not depend on
// the region. The status is the estimate's border status in the frame.
Features estimate_in_region(EdgeSource& edges, Estimator& est, Method m, Point2i inner,
                            const Rect* last, Point2d velocity, const Params& params,
                            const EstimateOptions& options, const TrackerParams& tp, Trace* trace);

}  // namespace projtrack
