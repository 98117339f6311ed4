// Draws on the video what the tracker did and what it says, so that a person can read it: the
// method's trace as the paper's figures show it, the object's outline, and a text panel with the
// status (and why), x, y and depth.
#pragma once

#include <gst/video/video.h>

#include <string>
#include <vector>

#include "projtrack/method.hpp"
#include "projtrack/trace.hpp"
#include "projtrack/tracker.hpp"

namespace projtrack::gst {

// The panel's text for one frame: the status in capitals and why (lost, searching, waiting,
// invalid settings...), then x, y and depth and the centroid when there are any. Unwrapped.
std::vector<std::string> overlay_text(const TrackResult& r, Method method);

// The text's scale: glyphs of 5×7 pixels times this (2 at 640×480, 4 at 1080p).
int text_scale(int frame_height);

// Filled pixels (tinted cyan), grid lines (magenta), selected blocks (tinted blue, outlined),
// the last recorded iteration's rays (green) and their hits (yellow), the object's outline (green,
// the appearance model), the bounding box (red while tracking, orange when held after a loss), the
// centroid (red cross), the updated inner point (yellow square), and the text panel at the top
// left on a darkened background, its first line coloured by the status. Works on every supported
// format: each colour is written component by component through the format's plane, offset and
// subsampling.
void draw_overlay(GstVideoFrame* frame, Method method, const TrackResult& result,
                  const Trace& trace);

}  // namespace projtrack::gst
