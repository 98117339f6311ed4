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
  cv::Rect filled;  // the part of bgr and gray that holds this frame (the rest: a past one)
  cv::Mat ycrcb, chroma, cr, cb;  // buffers of build_work_images()

  cv::Size size() const { return gray.size(); }
};

// The tables that read video range (ColorView) as full range: OpenCV's gray and YCrCb are full
// range, and the flow model's flow and colours were measured on full-range frames (DAVIS through
// Python's BGR). One row of 256 each: luma, then chroma.
struct FullRangeTables {
  FullRangeTables();
  cv::Mat luma, chroma;
};
const FullRangeTables& full_range_tables();

// The work size of a width × height frame at `scale`: ceil(width / scale) × ceil(height / scale).
cv::Size work_size(int width, int height, int scale);
// The frame pixels work rectangle `region` at `scale` covers, within the width × height frame.
cv::Rect frame_part(const cv::Rect& region, int scale, int width, int height);

// `frame` at `scale`: luma averaged over each block, chroma resampled to it, both read from the
// frame's video range as full range (OpenCV's); a gray frame's colour is its luma. Reuses
// `out`'s buffers.
void build_work_images(const ColorView& frame, int scale, WorkImages& out);
// The same within `region` (work px) only: the images are of the whole work size, and only
// `region` (clipped to it; out.filled) holds this frame. The cost of a part is the part's.
void build_work_images(const ColorView& frame, int scale, const cv::Rect& region, WorkImages& out);

}  // namespace projtrack
