// A colour view of any supported frame: the YUV planes in place, or packed RGB converted once.
#pragma once

#include <gst/video/video.h>

#include <cstdint>
#include <vector>

#include "projtrack/color_view.hpp"

namespace projtrack::gst {

// True for the formats whose plane 0 is 8-bit luma (read in place, never converted).
bool has_luma_plane(GstVideoFormat format);
// True for packed YUV: 4:2:2 (YUY2, UYVY: luma every second byte, chroma between) and AYUV
// (4:4:4, alpha first, luma every fourth byte).
bool is_packed_yuv(GstVideoFormat format);

// For YUV formats, views of the luma and chroma planes with their strides and subsampling (GRAY8:
// luma only); for packed YUV (YUY2, UYVY, AYUV), the chroma in place and the luma gathered into
// `buffer`; for packed RGB, `buffer` (reused across frames) receives the BT.601 luma and
// half-resolution chroma.
ColorView frame_color(const GstVideoFrame* frame, std::vector<std::uint8_t>& buffer);

}  // namespace projtrack::gst
