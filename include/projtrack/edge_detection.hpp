// Edge detection into a reusable edge map (non-zero = edge), the estimators' input.
#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "geometry.hpp"
#include "image_view.hpp"

namespace projtrack {

class CannyDetector;  // src/edges/canny.hpp
class WorkBudget;

enum class EdgeDetector {
  Canny,  // Canny's, hysteresis thresholds low/high (L1 gradient, 3×3 Sobel): as cv::Canny
  Sobel,  // |Gx| + |Gy| of the 3×3 Sobel >= low: thick edges, as the original system used
  Input,  // the image already is an edge map: above the black level = edge
};

inline constexpr int kMaxBlurPasses = 16;

struct EdgeParams {
  EdgeDetector detector = EdgeDetector::Canny;
  // Gradient thresholds on the |Gx| + |Gy| scale of a 3×3 Sobel, where a step of contrast C
  // (grey levels) scores 4·C. Canny: hysteresis; EdgeMap swaps them if low > high, validate()
  // reports it (the tracker refuses such settings). Sobel: `low` only.
  double low = 50;
  double high = 150;
  int blur = 1;  // 3×3 box-blur passes before detecting (0 = none; the original system used 2)
  // EdgeDetector::Input: the value of "no edge". 0 reads the image in place (non-zero = edge);
  // limited-range video stores black as 16, so an edge map there is luma > 16.
  int input_black_level = 0;
};

// Empty when the parameters work together; otherwise says what conflicts (Canny's low threshold
// above its high one) or is not a number.
std::string validate(const EdgeParams& params);

// Owns the edge and blur buffers and reuses them: after the first frame of a given size, detect()
// does not allocate.
class EdgeMap {
 public:
  EdgeMap();
  ~EdgeMap();
  EdgeMap(EdgeMap&&) noexcept;
  EdgeMap& operator=(EdgeMap&&) noexcept;

  // Detects the edges of `gray` and returns a view of them, valid until the next call (for
  // EdgeDetector::Input with black level 0: `gray` itself). An empty or invalid `gray` gives an
  // empty view; out-of-range parameters are clamped (negative thresholds to 0, blur to
  // [0, kMaxBlurPasses]).
  ImageView detect(const ImageView& gray, const EdgeParams& params);
  // The edges of `region` of `gray` only (a view of region.width × region.height): what a tracker
  // needs around its object, at a fraction of the cost. The first filter reads the real pixels
  // around the region; within a few pixels of the region's own border the edges may differ from
  // the whole frame's. `region` is clipped to the frame; an empty region gives an empty view.
  // With a budget (work_budget.hpp), the work is spent from it and checked between blur passes
  // and every few rows of Canny: once it runs out (or its stop flag is set), what was not reached
  // is left without edges (budget->ran_out() or interrupted() say the view is incomplete).
  ImageView detect(const ImageView& gray, const EdgeParams& params, const Rect& region,
                   WorkBudget* budget = nullptr);

 private:
  // Buffers sized for the largest region seen; each call wraps the part it needs, so a region
  // that changes size from frame to frame does not reallocate.
  template <class T>
  cv::Mat wrap_buffer(std::vector<T>& buffer, int rows, int cols, int type);
  std::vector<std::uint8_t> blurred_[2],
      edges_;  // edges_: Sobel and thresholded input; Canny has its own
  std::vector<std::int16_t> gx_, gy_;
  std::unique_ptr<CannyDetector> canny_;  // its buffers: a stage of src/, not of the API
};

}  // namespace projtrack
