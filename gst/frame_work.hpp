// One mapped frame's work: the seed given applied, the single track and the objects followed at
// once run on it, and the alpha and the overlay written into it. stream.cpp maps the frame before
// and reports after.
#pragma once

#include <gst/video/video.h>

#include <string>

#include "element.hpp"
#include "object_frames.hpp"

namespace projtrack::gst {

// What one mapped frame gave: the single track's result (when it ran) and the objects'.
struct FrameOutcome {
  TrackResult single;
  bool single_ran = true;
  ObjectsFrame objects;
};

// Runs the single track (after the seed given, if any: why it could not be applied goes into
// `note`) and the objects (started anew from their lists when `restart`) on one mapped frame, and
// draws and writes the alpha when asked.
FrameOutcome process(GstProjtrack* self, GstVideoFrame* frame, const ElementSettings& s,
                     SeedCommand command, bool restart, std::string& note);

}  // namespace projtrack::gst
