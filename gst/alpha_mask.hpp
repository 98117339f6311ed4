// The silhouette out as video: written into the alpha channel of formats that have one, so that
// compositor (or any element that blends by alpha) shows the object alone.
#pragma once

#include <gst/video/video.h>

#include <vector>

#include "projtrack/silhouette_mask.hpp"

namespace projtrack::gst {

// Whether the element writes `format`'s alpha (alpha-mask=true): AYUV, A420, BGRA, RGBA, ARGB,
// ABGR.
bool has_alpha(GstVideoFormat format);

// Sets the frame's alpha to 255 inside any of `silhouettes` and to 0 elsewhere (everywhere when
// none holds a pixel: no object measured on this frame). A silhouette is at its tracker's working
// scale, so its edge follows blocks of that many pixels.
void write_alpha(GstVideoFrame* frame, const std::vector<SilhouetteMask>& silhouettes);

}  // namespace projtrack::gst
