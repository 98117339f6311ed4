// A silhouette cut into the pieces an estimator can measure from one inner point each. A finger
// across the object cuts it apart; a neck narrower than the grid lets no grid line through. So
// the pieces are the parts left by an opening of the grid's half-width, and every pixel of the
// silhouette belongs to the piece it is nearest to within the silhouette.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mask.hpp"
#include "core/region_labels.hpp"

namespace projtrack {

class SilhouettePieces {
 public:
  // Splits `s`: an opening of radius `neck` (px), its 4-connected parts of at least `min_share`
  // of the silhouette's area, each grown back over the silhouette (by distance within it).
  // Returns the number of pieces (0 for an empty silhouette; 1 when nothing splits it).
  int split(const Mask& s, int neck, double min_share);
  // The whole silhouette as one piece (no split): 1, or 0 when it is empty.
  int whole(const Mask& s);
  // Piece i (0 = the largest) as a mask over s.rect(), and the point deepest in its core.
  const Mask& piece(int i);
  Point2i deepest(int i);
  // The piece that holds the frame pixel p, or -1.
  int piece_at(Point2i p) const;

 private:
  // Grows the cores' owners over the silhouette, breadth first.
  void grow();

  const Mask* silhouette_ = nullptr;
  Mask opened_, core_, piece_, tmp_, leftover_;
  RegionLabels cores_, rest_;
  std::vector<int> order_, label_of_;  // pieces by size; core label → piece index
  std::vector<std::int32_t> owner_;    // per pixel of s: piece index + 1, 0 = none
  std::vector<Point2i> queue_;
  Rect rect_;
  MaskOps ops_;
};

}  // namespace projtrack
