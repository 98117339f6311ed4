// Gap-tolerant grid filling (beyond the paper: its open problem of edge miscalculations). The
// m-grid fill, except that a grid line may not squeeze through a gap in the contour: a line that
// passes a narrow stretch — edges on both sides of it no farther apart than a break of max_gap
// px in a contour — and comes out into open space beyond is a leak, and stops before it.
#pragma once

#include <vector>

#include "estimators/grid_filling.hpp"

namespace projtrack {

// Grid lines, area and centroid as GridFilling's (count · m² / (2m − 1); the mean of the reached
// grid pixels). Beside every pixel of a run, on each side, the nearest edge pixel within
// max_gap + 1 px across the line is found; it counts only if it ends a contour (its edge
// neighbours form one arc of at most three pixels; outside the frame counts as edge; one-pixel
// specks are skipped and hide nothing). A run stops before the first pixel, walking out from its
// start, where contour ends on its two sides within max_gap + 1 px along it are no farther apart
// across it than a break of max_gap px: about max_gap + 2 px short of the gap. The sides of a
// narrow part of the object are unbroken contours, so lines pass between them, and on closed
// contours the answers are GridFilling's exactly.
// Where it still fails (docs/gap_tolerant_filling.md): breaks longer than max_gap, contour
// absent over long stretches (real footage against a similar background), spurious strokes.
class GapTolerantFilling final : public GridFilling {
 protected:
  // The plain grid run, cut before the first pixel where the line passes through a gap of up to
  // max_gap px; on a closed outline (EstimateOptions::closed_outline), the plain run itself.
  Span extend(const Context& ctx, bool vertical, int at, int start, Work& work) override;

 private:
  // Per position of the line being walked: the nearest edge on each side, and whether it ends a
  // contour (0: not yet known).
  std::vector<std::uint8_t> near1_, near2_, end1_, end2_;
};

}  // namespace projtrack
