// The object's silhouette as the object model finds it (the flow model; the edges model has
// none), for its users: a mask at the model's working scale, and its outline as polygons in
// frame coordinates.
#pragma once

#include <vector>

#include "geometry.hpp"
#include "image_view.hpp"

namespace projtrack {

// Work pixel (X, Y) at scale s covers frame pixels [sX, sX + s) × [sY, sY + s), clipped to the
// frame. A view: valid until the tracker's next frame.
struct SilhouetteMask {
  ImageView mask;  // one byte per work pixel of `rect`, non-zero inside the object
  Rect rect;       // the mask's rectangle, in work pixels
  int scale = 0;   // s, frame pixels per work pixel; 0: no silhouette
  int frame_width = 0, frame_height = 0;  // the frame's size, in pixels

  bool empty() const { return scale <= 0 || rect.empty() || mask.empty(); }
  // Whether frame pixel p lies inside the object.
  bool contains(Point2i p) const {
    if (empty() || p.x < 0 || p.y < 0) return false;
    const int x = p.x / scale - rect.x, y = p.y / scale - rect.y;
    return mask.contains(x, y) && mask.at(x, y) != 0;
  }
};

// The outline of `s`: one closed polygon per piece of the silhouette (the largest first; holes
// are not outlined), its vertices at the centres of the outline's frame pixels, simplified so
// that the outline lies within `tolerance` work pixels of its polygon (Douglas-Peucker). Empty
// for an empty silhouette.
std::vector<std::vector<Point2i>> outline_polygons(const SilhouetteMask& s, double tolerance = 1.0);

}  // namespace projtrack
