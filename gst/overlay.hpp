// Draws what the estimator did on the video frame, the way the paper's figures show it.
#pragma once

#include <gst/video/video.h>

#include "features.hpp"
#include "method.hpp"
#include "trace.hpp"

namespace projtrack::gst {

// Filled pixels (tinted cyan), grid lines (magenta), selected blocks (tinted blue, outlined),
// the last recorded iteration's rays (green) and their hits (yellow), the bounding box (red), the
// centroid (red cross) and the updated inner point (yellow square). Works on every supported
// format: each colour is written component by component through the format's plane, offset and
// subsampling.
void draw_overlay(GstVideoFrame* frame, Method method, const Features& features,
                  const Trace& trace);

}  // namespace projtrack::gst
