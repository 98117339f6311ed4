// Draws the objects followed at once (draw=true): each in its own colour, its outline, box and
// centroid as draw-flags asks, and its id (and its status when it is not tracked) as a label, so
// that a person tells them apart.
#pragma once

#include <gst/video/video.h>

#include "object_frames.hpp"
#include "settings.hpp"

namespace projtrack::gst {

void draw_objects(GstVideoFrame* frame, const ObjectsFrame& objects, unsigned flags = kDrawAll);

}  // namespace projtrack::gst
