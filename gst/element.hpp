// The element's instance, shared by the files that make up the element: which field is guarded by
// what, and the per-stream state.
#pragma once

#include <gst/gst.h>
#include <gst/video/video.h>

#include <atomic>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gstprojtrack.h"
#include "projtrack/tracker.hpp"
#include "settings.hpp"

GST_DEBUG_CATEGORY_EXTERN(gst_projtrack_debug);
#define GST_CAT_DEFAULT gst_projtrack_debug

namespace projtrack::gst {

// Per-stream state: created in set_info, dropped in stop; touched by the streaming thread only.
struct Stream {
  Tracker tracker;
  Trace trace;
  std::vector<std::uint8_t> converted;  // packed RGB frames converted to luma and chroma
  // Why buffers were not read since the caps: each reason is warned once.
  std::set<std::string> layout_warnings;
  int width = 0, height = 0;
  // The format and colours the tracker learned on: a change makes it learn them anew.
  GstVideoFormat format = GST_VIDEO_FORMAT_UNKNOWN;
  GstVideoColorRange range = GST_VIDEO_COLOR_RANGE_UNKNOWN;
  GstVideoColorMatrix matrix = GST_VIDEO_COLOR_MATRIX_UNKNOWN;
  int track_id = 0;          // of the current track (next_track_id()); 0 before the first
  std::string element_name;  // for the metas
  std::vector<std::vector<Point2i>> outline;  // this frame's silhouette, frame coordinates
  int black_level = 0;                        // of edge-detector=input: 16 in limited-range YUV
  guint64 frames = 0;                         // for buffers without timestamps
  TrackStatus last_status = TrackStatus::NoInnerPoint;
  // The status of the last message posted (updates=on-change).
  std::optional<TrackStatus> last_posted;
  std::string last_warning;  // the conflict last reported by an element warning
};

}  // namespace projtrack::gst

struct _GstProjtrack {
  GstVideoFilter parent;
  projtrack::gst::Settings* settings;   // GST_OBJECT_LOCK
  projtrack::gst::SeedCommand pending;  // GST_OBJECT_LOCK
  // GST_OBJECT_LOCK: why a seed given was refused (a malformed box), for the streaming thread to
  // warn of (it posts, never under the lock) and to say in the next message's detail.
  std::string* seed_note;
  int frame_width, frame_height;   // GST_OBJECT_LOCK: the negotiated size, for clicks
  int tracked_x, tracked_y;        // GST_OBJECT_LOCK: the tracker's inner point after the
                                   // last frame (current-inner-point-x/y); -1 = none
  projtrack::gst::Stream* stream;  // streaming thread
  // Set when the streaming thread must drop what it is doing (PAUSED → READY, a flush): the
  // tracker polls it at its checkpoints; cleared when streaming starts again.
  std::atomic<bool>* interrupt;
};
