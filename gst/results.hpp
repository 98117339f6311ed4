// What the element says about a frame: the ROI meta and GstProjtrackMeta on the buffer and the
// projtrack element message (docs/element.md, "Results"), and which frames post one.
#pragma once

#include <gst/gst.h>

#include <optional>
#include <string>
#include <vector>

#include "gstprojtrack.h"
#include "projtrack/method.hpp"
#include "projtrack/tracker.hpp"
#include "settings.hpp"

namespace projtrack::gst {

// One frame's report: the tracker's result and what the element adds to it.
struct FrameReport {
  const TrackResult& result;
  Method method;
  const char* element;  // the element's name
  int track_id;         // of the track the features belong to; 0: none
  int width, height;    // the frame's
  // The silhouette's outline on this frame (tracking with the flow model), frame
  // coordinates, one polygon per piece.
  const std::vector<std::vector<Point2i>>& outline;
  std::string note;  // said in the message's detail besides the tracker's (a refused seed)
};

// A new track id: unique in the process (every projtrack element, every track), > 0.
int next_track_id();

// While tracking: a GstVideoRegionOfInterestMeta of type "object" with the box, id track_id (an
// object among several: its own id) and
// the features as its "projtrack" parameter structure, and a GstProjtrackMeta with the same.
void attach_meta(GstBuffer* buffer, const FrameReport& report);

// The projtrack element message of one frame (not posted: post it without the object lock).
GstMessage* result_message(GstProjtrack* self, GstBuffer* buffer, const FrameReport& report,
                           guint64 processing_ns);

// Whether this frame posts a message: every frame; on a change (another status, an acquisition,
// a push); or never. `last` is the status of the last frame, updated.
bool worth_posting(Updates updates, const TrackResult& r, std::optional<TrackStatus>& last);

}  // namespace projtrack::gst
