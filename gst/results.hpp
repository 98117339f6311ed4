// What the element says about a frame: the ROI meta on the buffer and the projtrack element
// message (docs/element.md, "Results"), and which frames post one.
#pragma once

#include <gst/gst.h>

#include <optional>

#include "gstprojtrack.h"
#include "projtrack/method.hpp"
#include "projtrack/tracker.hpp"
#include "settings.hpp"

namespace projtrack::gst {

// A GstVideoRegionOfInterestMeta of type "object" with the box, and the features as its
// "projtrack" parameter structure.
void attach_meta(GstBuffer* buffer, const TrackResult& r, Method method);

// The projtrack element message of one frame (not posted: post it without the object lock).
GstMessage* result_message(GstProjtrack* self, GstBuffer* buffer, const TrackResult& r,
                           Method method, guint64 processing_ns);

// Whether this frame posts a message: every frame; on a change (another status, an acquisition,
// a push); or never. `last` is the status of the last frame, updated.
bool worth_posting(Updates updates, const TrackResult& r, std::optional<TrackStatus>& last);

}  // namespace projtrack::gst
