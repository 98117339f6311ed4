// The frame as the flow model reads it: the whole frame at an integer working scale, as colour
// (BGR, what the colour mixture counts) and gray (what the flow compares).
#pragma once

#include <opencv2/core.hpp>

#include "projtrack/color_view.hpp"

namespace projtrack {

struct WorkImages {
  cv::Mat bgr, gray;  // ceil(width / scale) × ceil(height / scale)
  int scale = 1;      // work pixel (X, Y) covers frame pixels [sX, sX + s) × [sY, sY + s)
  int frame_width = 0, frame_height = 0;
  cv::Mat ycrcb, chroma, cr, cb;  // buffers of build_work_images()

  cv::Size size() const { return gray.size(); }
};

// `frame` at `scale`: luma averaged over each block, chroma resampled to it, both read from the
// frame's video range as full range (OpenCV's); a gray frame's colour is its luma. Reuses
// `out`'s buffers.
void build_work_images(const ColorView& frame, int scale, WorkImages& out);

}  // namespace projtrack
