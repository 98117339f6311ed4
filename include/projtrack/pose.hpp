// The 3D pointer a tracked object gives: x and y from its centroid, depth from its area.
#pragma once

namespace projtrack {

// x, y in [-1, 1] from the centroid (0 at the frame centre, +1 at the right and bottom edges);
// depth √(area ÷ the frame's area), the object's side as a share of the frame's: it rises as the
// object nears the camera. One rule, whatever started the track (a point, a box, acquisition)
// and across losses and re-acquisitions: nothing is reset, so depth changes only as the object's
// size does (and keeps its value when the frame is scaled).
struct Pose {
  double x = 0, y = 0, depth = 0;
};

}  // namespace projtrack
