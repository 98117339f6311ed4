// The object's silhouette on one frame, from three cues that fail in different places: the
// appearance model's likelihood (it tells the object from the hand and the wall, but not along
// a colour it shares with them), the edges (they follow the outline closely, but are open at
// junctions and cut the object into printed pieces) and the prior (the last silhouette moved by
// the object's motion: the object cannot jump).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mask.hpp"
#include "core/region_labels.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/image_view.hpp"

namespace projtrack {

struct SilhouetteParams {
  // How far, px, the silhouette may reach beyond the prior.
  int reach = 12;
  // Edge-bounded regions smaller than this share of the expected area are taken or left whole,
  // by their mean likelihood (a print, a highlight, a finger); larger ones, which may have leaked
  // through a gap in the edges, pixel by pixel.
  double small_region = 1.25;
  // A piece of the object apart from the rest (a finger cuts across it) must hold at least this
  // share of the expected area.
  double min_piece = 0.03;
  // Keep every such piece within reach of the prior, not only those that lie mostly on it: for a
  // first silhouette, which may hold only the part of the object on one side of a finger.
  bool all_pieces_in_reach = false;
};

class SilhouetteSegmenter {
 public:
  // The silhouette in `roi` (frame coordinates) into `out`: object-like pixels (likelihood of at
  // least one half) within `reach` of `prior`, edge pixels between two of them; of those, the
  // 4-connected pieces that hold `hint` or lie mostly on the prior (else the one that overlaps it
  // most), their holes filled: a projection has none. `likelihood` and `edges` cover `roi` (row
  // stride roi.width for the likelihood). False when nothing object-like is left.
  bool segment(const std::vector<std::uint8_t>& likelihood, const ImageView& edges, const Rect& roi,
               const Mask& prior, double expected_area, Point2i hint, const SilhouetteParams& p,
               Mask& out);

 private:
  RegionLabels regions_, components_;
  std::vector<std::uint32_t> sums_;
  std::vector<std::int64_t> overlap_;
  std::vector<std::uint8_t> keep_, cut_;
  Mask prior_, near_;
  MaskOps ops_;
};

}  // namespace projtrack
