// m-grid-filling (the paper's proposal): fill only along a grid of m×m cells anchored at the inner
// point, so a gap in the contour leaks only where a grid line crosses it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scratch_mask.hpp"
#include "projtrack/estimator.hpp"

namespace projtrack {

// Grid lines: the rows y ≡ seed.y and columns x ≡ seed.x (mod m). The fill walks along them
// 4-connected, run by run. Centroid: the mean of the reached grid pixels. Area: their count
// scaled to px²: a region of A px² holds about A/m² cells of 2m − 1 grid pixels each, so
// area = count · m² / (2m − 1) (exact pixel-filling when m = 1).
class GridFilling : public Estimator {
 protected:
  void run(const Context& ctx, Features& out, Work& work) override;

  // A run along one grid line: positions [first, last], x on a row, y on a column.
  struct Span {
    int first, last;
  };
  // How far the line through the free pixel `start` runs: the row `at` (vertical = false) or the
  // column `at`. Here up to an edge, the border or pixels this line already reached; a variant
  // of the fill changes only this.
  virtual Span extend(const Context& ctx, bool vertical, int at, int start, Work& work);

  static constexpr std::uint8_t kAlongRow = 1, kAlongColumn = 2;  // bits of reached_
  ScratchMask reached_;  // bit 1: reached along its row, bit 2: along its column

 private:
  struct Pending {
    Point2i p;
    bool vertical;
  };
  std::vector<Pending> pending_;
};

}  // namespace projtrack
