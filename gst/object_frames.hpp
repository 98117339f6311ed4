// The objects followed at once on one frame: the MultiTracker run on the frame the single track
// ran on, each object's outline, which of them post a message; then each object's metas and
// message, as the single track's (results.hpp) with the object's `id`.
#pragma once

#include <gst/gst.h>

#include <string>
#include <vector>

#include "element.hpp"
#include "projtrack/color_view.hpp"

namespace projtrack::gst {

// What the objects did on one frame, one entry per object followed, in the order of their ids.
struct ObjectsFrame {
  std::vector<TrackResult> results;
  std::vector<std::vector<std::vector<Point2i>>> outlines;  // frame coordinates, per object
  std::vector<int> track_ids;                               // per object
  std::vector<bool> posts;  // whether the object's message is posted (`updates`, per object)
  std::vector<std::string> refused;  // starts of start-boxes/-points refused on a restart
};

// The streaming thread, with objects_mutex held: restarts the objects from the lists when asked,
// then tracks them on `color` (taken at `t` seconds). Nothing when no object is followed.
ObjectsFrame track_objects(Objects& objects, const ColorView& color, double t,
                           const Settings& bundle, const ElementSettings& s, bool restart,
                           int width, int height);

// Every object's metas (while it has features) and message (when it posts), with its `id`.
// Without any lock: messages are posted.
void report_objects(GstProjtrack* self, GstBuffer* buffer, const ElementSettings& s,
                    const ObjectsFrame& frame, guint64 processing_ns);

}  // namespace projtrack::gst
