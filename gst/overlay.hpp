// Draws on the video what the tracker did and what it says, so that a person can read it: the
// method's trace as the paper's figures show it, the object's outline, its box, centroid and inner
// point, and the text panel (hud.hpp); draw-flags chooses which.
#pragma once

#include <gst/video/video.h>

#include "hud.hpp"
#include "projtrack/method.hpp"
#include "projtrack/trace.hpp"
#include "projtrack/tracker.hpp"
#include "settings.hpp"

namespace projtrack::gst {

// Of what `flags` (DrawFlag bits) asks for: filled pixels (tinted cyan), grid lines (magenta),
// selected blocks (tinted blue, outlined), the last recorded iteration's rays (green) and their
// hits (yellow); the object's outline (green, the flow model's); the bounding box (red while
// tracking, orange when held after a loss); the centroid (red cross); the updated inner point
// (yellow square); the text panel. Works on every supported format: each colour is written
// component by component through the format's plane, offset and subsampling.
void draw_overlay(GstVideoFrame* frame, Method method, const TrackResult& result,
                  const Trace& trace, unsigned flags = kDrawAll);

}  // namespace projtrack::gst
