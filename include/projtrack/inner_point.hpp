// The inner point: finding a free pixel to start from, and the update common to every method.
#pragma once

#include <optional>
#include <vector>

#include "geometry.hpp"
#include "image_view.hpp"
#include "rays.hpp"
#include "trace.hpp"

namespace projtrack {

// The free (non-edge) pixel nearest to `p` within `radius` px (Euclidean), `p` itself when it is
// free; none when every candidate is an edge or outside the frame.
std::optional<Point2i> nearest_free_pixel(const ImageView& edges, Point2i p, int radius);

// Walks from `from` (free) toward `to` one pixel at a time and returns where it stops: `to`, or
// the last free pixel before an edge or the frame border.
Point2i move_toward(const ImageView& edges, Point2i from, Point2i to, Work& work);

// Casts the fan from `p` and walks toward the mean of its hits (never jumping across an edge:
// on a ring the mean lies in the hole, and the walk stops at the inner contour instead).
Point2i recentre(const ImageView& edges, Point2i p, const RayFan& fan, std::vector<RayHit>& scratch,
                 Work& work, Trace* trace, int iteration);

// The paper's inner-point update: move toward the new centroid until reaching it or an edge,
// then recentre on the mean of n ray hits, so the point stays well inside for the next frame.
Point2i update_inner_point(const ImageView& edges, Point2i p, Point2d centroid, const RayFan& fan,
                           std::vector<RayHit>& scratch, Work& work, Trace* trace, int iteration);

}  // namespace projtrack
