// What a start keeps of its cut: the pieces of the object (from a click the one under it; from a
// box every piece of at least a tenth of the largest), how well their outline is the picture's
// own (a click chooses its square by it), and the kept object written into the working frame.
#pragma once

#include <opencv2/core.hpp>

#include "segmentation/cut_problem.hpp"
#include "segmentation/start_cut.hpp"

namespace projtrack {

// out.kept from out.probability.
void keep_pieces(const CutProblem& problem, CutWorkspace& ws, CutResult& out);
// out.contrast and out.touch along out.kept's outline.
void score_outline(const CutProblem& problem, const ContrastField& field, CutResult& out);
// What write_cut() costs into an `out_size` mask of a width × height frame, work units.
std::uint64_t write_cost(const CutProblem& problem, int width, int height, cv::Size out_size);
// The kept object of `cut` into `mask` (CV_8U of `out_size`, the frame's size at another scale):
// zero but where the cut's probabilities, upsampled, are over ½.
void write_cut(const CutProblem& problem, const CutResult& cut, int width, int height,
               cv::Size out_size, cv::Mat& mask);

}  // namespace projtrack
