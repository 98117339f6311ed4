// Motion as evidence about the object: the previous silhouette carried along the flow (a prior),
// and how much more each pixel moves like the object than like its surroundings.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace projtrack {

// The bounding box of the pixels of `values` (one channel) above 0; `buffer` is a buffer.
cv::Rect support_of(const cv::Mat& values, cv::Mat& buffer);

// `r` grown by `by` pixels on every side, within `size`.
cv::Rect grown_within(const cv::Rect& r, int by, cv::Size size);

// The pixels within `width` (a square's half-side) of `inside` (CV_8U) but not in it: computed
// as a box sum (the same pixels as a dilation by the square, at a cost that does not grow with
// its width) in `inside`'s box grown by `width`, which is returned; `around` (CV_8U, that box's
// size) is set on the ring. `count` is a buffer.
cv::Rect square_ring(const cv::Mat& inside, int width, cv::Mat& count, cv::Mat& around);

// The largest |component| of `flow` (CV_32F, any channels): how far any pixel moved along x or
// y (a NaN in `flow` may or may not show: carry_along_flow reads one as outside the frame).
float largest_component(const cv::Mat& flow);

// `last` (CV_32F, values in [0, 1], the last frame's silhouette, zero outside `held`) moved to
// this frame along the backward flow `flow` (DenseFlow::backward(), zero outside `moving`): each
// pixel takes the value where it came from (0 from outside the frame). Only the returned box of
// `prior` is written: the rest must hold zeros (a `prior` of another size or type is made anew,
// zero). `map` is a buffer.
cv::Rect carry_along_flow(const cv::Mat& last, const cv::Rect& held, const cv::Mat& flow,
                          const cv::Rect& moving, cv::Mat& map, cv::Mat& prior);

// The object's and its surroundings' motions: the median flow inside the prior and in a ring
// around it (`ring` × √area wide).
struct MotionSplit {
  cv::Point2f object, surroundings;
  float separation = 0;  // how far apart the two motions are, work px a frame
  bool valid = false;    // both regions have pixels
};
// `count`, `around` and `samples` are buffers (a ring of a large object spans most of the frame:
// kept from frame to frame, they are not allocated and paged in again each time).
MotionSplit split_motion(const cv::Mat& flow, const cv::Mat& inside, double ring, cv::Mat& count,
                         cv::Mat& around, std::vector<float>& samples);

// Adds to `log_odds` (CV_32F) each pixel's evidence of moving with the object rather than with
// its surroundings: a Gaussian log-likelihood ratio whose spread is half the motions' separation,
// clamped to ±`clamp` (motion is one cue of several). Nothing when the two motions are closer
// than `min_separation` work px: then motion tells nothing apart.
// Where `damped` (CV_8U, log_odds' size; empty: nowhere) is set, the evidence counts at
// `damped_share` of its value.
void add_motion_evidence(const cv::Mat& flow, const MotionSplit& split, double clamp,
                         double min_separation, cv::Mat& log_odds, const cv::Mat& damped = {},
                         double damped_share = 1);

}  // namespace projtrack
