// Gap-tolerant grid filling (beyond the paper: its open problem of edge miscalculations). The
// m-grid fill, except that a grid line may not squeeze through a gap in the contour: a line that
// passes a narrow stretch — edges on both sides of it no farther apart than a break of max_gap
// px in a contour — and comes out into open space beyond is a leak, and stops before it.
#pragma once

#include <vector>

#include "estimator.hpp"
#include "scratch_mask.hpp"

namespace projtrack {

// Grid lines, area and centroid as GridFilling's (count · m² / (2m − 1); the mean of the reached
// grid pixels). A pixel of a line is narrow when, within a window of g + 1 px along the line
// (g = max_gap), the nearest edges on its two sides are at most g + 1 px apart across it — the
// two ends of a break of up to g px in one contour — where two sides of an object part are
// farther apart. Walking a line, a narrow stretch that ends at an edge, the border or pixels
// already reached belongs to the object (a corner); one that opens into wide free pixels is a
// gap, and the line stops where the stretch began.
// Where it still fails (docs/gap_tolerant_filling.md): gaps longer than max_gap, and parts of
// the object no wider than max_gap, which a line entering from a wide part treats as a gap.
class GapTolerantFilling final : public Estimator {
 public:
  Method method() const override { return Method::GapTolerantFilling; }

 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  struct Pending {
    Point2i p;
    bool vertical;
  };
  struct Span {
    int first, last;
  };
  Span walk(const ImageView& edges, bool vertical, int at, int start, int gap, Work& work);

  ScratchMask reached_;  // bit 1: reached along its row, bit 2: along its column
  std::vector<Pending> pending_;
  // Per position of the line being walked: the nearest edge on each side, and whether it ends a
  // contour (0: not yet known).
  std::vector<std::uint8_t> near1_, near2_, end1_, end2_;  // per position of the line being walked
};

}  // namespace projtrack
