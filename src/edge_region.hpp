// The edges model's estimate on the edges around the object only: a region predicted from the
// last box and its motion, grown until it no longer cuts the estimate.
#pragma once

#include "edge_source.hpp"
#include "estimator.hpp"
#include "tracker_params.hpp"

namespace projtrack {

// The estimate of `est` from `inner` on the edges of `edges`: around `last` (the last accepted
// box) and that box moved by `velocity` (px a frame), grown by TrackerParams::edge_margin, when
// there is a last box and the region holds the inner point; else on the whole frame. An estimate
// that reaches the region's border (where it is not the frame's) is redone on a larger region,
// then on the whole frame, so that the answer does not depend on the region. The status is the
// estimate's border status in the frame.
Features estimate_in_region(EdgeSource& edges, Estimator& est, Method m, Point2i inner,
                            const Rect* last, Point2d velocity, const Params& params,
                            const TrackerParams& tp, Trace* trace);

}  // namespace projtrack
