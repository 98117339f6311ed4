// The 3D pointer a tracked object gives: x and y from its centroid, depth from its area.
#pragma once

namespace projtrack {

// x, y in [-1, 1] from the centroid (0 at the frame centre, +1 at the right and bottom edges);
// depth 1 when the object was first acquired, then sqrt(area / area then): it rises as the
// object nears the camera.
struct Pose {
  double x = 0, y = 0, depth = 1;
};

}  // namespace projtrack
