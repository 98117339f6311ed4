// A gray view of any supported frame: the luma plane in place, or packed RGB converted once.
#pragma once

#include <gst/video/video.h>

#include <cstdint>
#include <vector>

#include "image_view.hpp"

namespace projtrack::gst {

// True for the formats whose plane 0 is 8-bit luma (read in place, never converted).
bool has_luma_plane(GstVideoFormat format);

// For luma formats, a view of plane 0 with its stride; for packed RGB, `buffer` (reused across
// frames) receives the BT.601 gray image.
ImageView frame_gray(const GstVideoFrame* frame, std::vector<std::uint8_t>& buffer);

}  // namespace projtrack::gst
