// The duels, one function per family of routines; each writes its rows to handwritten.csv.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "duel.hpp"
#include "inputs.hpp"

namespace projtrack::handwritten {

// Per-pixel work on whole frames (cases_pixels.cpp): Canny, the box blur, RGB to gray and chroma,
// YUY2's luma, the work frame.
void pixel_duels(const std::vector<Frame>& frames, const Effort& e, std::FILE* out);

// Mask operations (cases_masks.cpp): labelling, dilate, erode, convex hull, the deepest point
// (chamfer distance), filling holes, moments.
void mask_duels(const std::vector<MaskInput>& masks, const Effort& e, std::FILE* out);

// The overlay's text (cases_text.cpp): the 5×7 font through the painter, against cv::putText.
void text_duels(const std::vector<Frame>& frames, const Effort& e, std::FILE* out);

// "yes" when `a` and `b` hold the same pixels, else "no" and how many pixels differ.
std::string same_pixels(const cv::Mat& a, const cv::Mat& b);

}  // namespace projtrack::handwritten
