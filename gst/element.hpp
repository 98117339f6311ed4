// The element's instance, shared by the files that make up the element: what other threads set
// (Locked, under the object lock), the per-stream state (Stream, the streaming thread's), and the
// flag that interrupts a frame.
#pragma once

#include <gst/gst.h>
#include <gst/video/video.h>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "frame_color.hpp"
#include "gstprojtrack.h"
#include "projtrack/multi_tracker.hpp"
#include "projtrack/tracker.hpp"
#include "settings.hpp"

GST_DEBUG_CATEGORY_EXTERN(gst_projtrack_debug);
#define GST_CAT_DEFAULT gst_projtrack_debug

namespace projtrack::gst {

// The objects followed at once beside the single track (start-boxes, start-points, add-box,
// add-point, click-adds), each with the MultiTracker's id (from 1). Under State::objects_mutex:
// the application's threads add and remove objects while the streaming thread tracks them.
struct Objects {
  // max-objects is enforced by the element (it may change while playing); the library's own
  // limit is the property's top.
  MultiTracker tracker{static_cast<std::size_t>(kMaxObjects)};
  // Per id: the status of the last message posted (updates=on-change), as Stream::last_posted.
  std::map<int, std::optional<TrackStatus>> last_posted;
  // Per id: the track-id of its features (next_track_id(), new on every acquisition), so that
  // every projtrack structure names its track as the single track's does.
  std::map<int, int> track_ids;
};

// Per-stream state: created in set_info, dropped in stop; touched by the streaming thread only.
struct Stream {
  Tracker tracker;
  Trace trace;
  FrameBuffers converted;  // frames converted to the tracker's luma and chroma (frame_color)
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
  guint64 frames = 0;                         // for buffers without timestamps
  TrackStatus last_status = TrackStatus::NoInnerPoint;
  // The status of the last message posted (updates=on-change).
  std::optional<TrackStatus> last_posted;
  std::string last_warning;  // the conflict last reported by an element warning
  Objects objects;           // under State::objects_mutex
};

// What the application's threads (properties, signals, clicks) and the streaming thread share:
// every field under GST_OBJECT_LOCK.
struct Locked {
  ElementSettings settings;
  SeedCommand pending = SeedCommand::None;
  // Why a seed given was refused (a malformed box), for the streaming thread to warn of (it posts,
  // never under the lock) and to say in the next message's detail.
  std::string seed_note;
  int frame_width = 0, frame_height = 0;  // the negotiated size, for clicks
  // The tracker's inner point after the last frame (current-inner-point-x/y); -1 = none.
  int tracked_x = -1, tracked_y = -1;
  // start-boxes or start-points were set (or a flush, a restart): the streaming thread starts the
  // objects anew from them before its next frame.
  bool restart_objects = false;
  // Starts refused by start-boxes or start-points (a malformed tuple), for the streaming thread to
  // warn of (it posts, never under the lock).
  std::string objects_note;
};

// The element's C++ state: made in instance init, freed in finalize.
struct State {
  Locked locked;                   // GST_OBJECT_LOCK
  std::unique_ptr<Stream> stream;  // the streaming thread's; null outside set_info .. stop
  // Guards `stream` being made or dropped, and stream->objects, against the threads that add and
  // remove objects (signals, clicks). Taken before the object lock, never inside it, and never
  // held while a message is posted (a bus sync handler may add an object).
  std::mutex objects_mutex;
  // Set when the streaming thread must drop what it is doing (PAUSED → READY, a flush): the
  // tracker polls it at its checkpoints; cleared when streaming starts again.
  std::atomic<bool> interrupt{false};
};

}  // namespace projtrack::gst

struct _GstProjtrack {
  GstVideoFilter parent;
  projtrack::gst::State* state;
};
