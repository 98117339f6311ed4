// A colour view of any supported frame at the video range the tracker reads (ColorView): the YUV
// planes in place, packed RGB converted once, a full-range frame (GRAY8, JPEG's YUV) mapped once.
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

// What frame_color() writes into, reused from frame to frame.
struct FrameBuffers {
  std::vector<std::uint8_t> read;         // gathered luma or chroma, RGB converted
  std::vector<std::uint8_t> video_range;  // a full-range frame mapped to video range
};

// For limited-range YUV formats, views of the luma and chroma planes with their strides and
// subsampling; for packed YUV (YUY2, UYVY, AYUV), the chroma in place and the luma gathered; for
// packed RGB, the video-range BT.601 luma and half-resolution chroma (packed_rgb_to_color); a
// full-range frame (GRAY8 and any YUV whose caps say range 0-255) mapped to video range.
ColorView frame_color(const GstVideoFrame* frame, FrameBuffers& buffers);

}  // namespace projtrack::gst
