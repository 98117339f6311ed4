// m-grid-filling (the paper's proposal): fill only along a grid of m×m cells anchored at the inner
// point, so a gap in the contour leaks only where a grid line crosses it.
#pragma once

#include <vector>

#include "estimator.hpp"
#include "scratch_mask.hpp"

namespace projtrack {

// Grid lines: the rows y ≡ seed.y and columns x ≡ seed.x (mod m). The fill walks along them
// 4-connected, run by run. Centroid: the mean of the reached grid pixels. Area: their count
// scaled to px²: a region of A px² holds about A/m² cells of 2m − 1 grid pixels each, so
// area = count · m² / (2m − 1) (exact pixel-filling when m = 1).
class GridFilling final : public Estimator {
 public:
  Method method() const override { return Method::GridFilling; }

 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

 private:
  struct Pending {
    Point2i p;
    bool vertical;
  };
  ScratchMask reached_;  // bit 1: reached along its row, bit 2: along its column
  std::vector<Pending> pending_;
};

}  // namespace projtrack
