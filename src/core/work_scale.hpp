// Work coordinates: the frame read at a coarser, integer working scale. Work pixel (X, Y) at scale
// s covers frame pixels [sX, sX + s) × [sY, sY + s); a model's silhouette is a mask at its scale.
#pragma once

#include "projtrack/geometry.hpp"

namespace projtrack {

// The work scale that makes `pixels` frame pixels about `target` work pixels (at least 1).
int work_scale(double pixels, double target);
// The work rectangle of a frame rectangle (every block it touches), and back (the blocks' pixels,
// clipped to a width × height frame).
Rect to_work(const Rect& frame_rect, int scale);
Rect to_frame(const Rect& work_rect, int scale, int width, int height);

}  // namespace projtrack
