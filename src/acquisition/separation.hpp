// How well a region's colours tell it from its surroundings': what a tracker that learns the
// object's colours against a ring around it (appearance/) can expect of that region.
#pragma once

#include "core/mask.hpp"
#include "projtrack/color_view.hpp"

namespace projtrack {

// 1 − the Bhattacharyya coefficient of the colour histograms (coarse bins: 8 of luma, 8 × 8 of
// chroma) of `region` and of the ring around it, as wide as a quarter of the region's √area (at
// least 2 px); `region` and `frame` in the same (work) coordinates, `frame` starting at (0, 0).
// 0: the same colours; 1: none in common. 0 for an empty region or ring.
double colour_separation(const ColorView& frame, const Mask& region, MaskOps& ops, Mask& scratch);

}  // namespace projtrack
