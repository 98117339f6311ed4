// Where the tracker gets its edges: a given edge map of the whole frame, or edges computed on
// demand for the region it needs.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "projtrack/edge_detection.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/image_view.hpp"
#include "projtrack/work_budget.hpp"

namespace projtrack {

class EdgeSource {
 public:
  explicit EdgeSource(const ImageView& frame_edges) : given_(frame_edges) {}
  EdgeSource(EdgeMap& map, const ImageView& gray, const EdgeParams& params)
      : map_(&map), gray_(gray), params_(params) {}
  // The frame the edges are of (its size is the frame's).
  const ImageView& frame() const { return map_ ? gray_ : given_; }
  // The parameters edges are detected with (defaults for given edges).
  const EdgeParams& params() const { return params_; }
  // The budget region() spends its work from (work_budget.hpp; null: none). Once it runs out,
  // regions come back incomplete (without edges where the work stopped).
  void set_budget(WorkBudget* budget) { budget_ = budget; }
  // The edges of `region` (clipped to the frame), valid until the next call.
  ImageView region(const Rect& r);
  // How far from a region's inner border its edges may differ from the whole frame's: the blur
  // passes after the first, and Canny's own 3×3 neighbourhood (0 for given edges).
  int border_guard() const { return map_ ? std::clamp(params_.blur, 0, kMaxBlurPasses) + 3 : 0; }

 private:
  ImageView given_;
  EdgeMap* map_ = nullptr;
  WorkBudget* budget_ = nullptr;
  ImageView gray_;
  EdgeParams params_;
};

}  // namespace projtrack
