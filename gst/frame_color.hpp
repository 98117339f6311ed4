// A colour view of any supported frame: the YUV planes in place, or packed RGB converted once.
#pragma once

#include <gst/video/video.h>

#include <cstdint>
#include <vector>

#include "projtrack/color_view.hpp"

namespace projtrack::gst {

// True for the formats whose plane 0 is 8-bit luma (read in place, never converted).
bool has_luma_plane(GstVideoFormat format);
// True for packed 4:2:2 YUV (YUY2, UYVY): luma every second byte, chroma between.
bool is_packed_yuv(GstVideoFormat format);

// For YUV formats, views of the luma and chroma planes with their strides and subsampling (GRAY8:
// luma only); for packed YUV (YUY2, UYVY), the chroma in place and the luma gathered into
// `buffer`; for packed RGB, `buffer` (reused across frames) receives the BT.601 luma and
// half-resolution chroma.
ColorView frame_color(const GstVideoFrame* frame, std::vector<std::uint8_t>& buffer);

}  // namespace projtrack::gst
