// The silhouette out as video: written into the alpha channel of formats that have one, so that
// compositor (or any element that blends by alpha) shows the object alone.
#pragma once

#include <gst/video/video.h>

#include "projtrack/silhouette_mask.hpp"

namespace projtrack::gst {

// Whether the element writes `format`'s alpha (alpha-mask=true): AYUV, A420, BGRA, RGBA, ARGB,
// ABGR.
bool has_alpha(GstVideoFormat format);

// Sets the frame's alpha to 255 inside `silhouette` and to 0 elsewhere (everywhere when it is
// empty: no object measured on this frame). The silhouette is at the tracker's working scale, so
// its edge follows blocks of that many pixels.
void write_alpha(GstVideoFrame* frame, const SilhouetteMask& silhouette);

}  // namespace projtrack::gst
