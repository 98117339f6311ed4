// Each buffer: the settings copied under the lock, the frame mapped after its layout is checked,
// the seed given applied, the tracker run, the alpha and the overlay written, the metas attached,
// the status logged and warned, and the message posted after the lock is released; and the
// stream's state across caps.
#include "stream.hpp"

#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "alpha_mask.hpp"
#include "element.hpp"
#include "frame_mapping.hpp"
#include "frame_work.hpp"
#include "object_frames.hpp"
#include "results.hpp"
#include "seeds.hpp"

namespace projtrack::gst {

namespace {

// A buffer whose layout does not fit its memory is not read: it passes through untouched, the
// track waits (a seed given meanwhile applies to the next readable frame), and the status says
// why. One element warning per reason and caps; the debug log has every frame.
TrackResult unread_frame(GstProjtrack* self, const FrameMapping& mapping, SeedCommand command,
                         bool restart) {
  GST_OBJECT_LOCK(self);
  if (self->state->locked.pending == SeedCommand::None) self->state->locked.pending = command;
  if (restart) self->state->locked.restart_objects = true;
  GST_OBJECT_UNLOCK(self);
  GST_DEBUG_OBJECT(self, "buffer not read (%s): %s", mapping.reason, mapping.detail.c_str());
  if (self->state->stream->layout_warnings.insert(mapping.reason).second) {
    GST_ELEMENT_WARNING(self, STREAM, FORMAT,
                        ("Video buffer not read (%s): %s", mapping.reason, mapping.detail.c_str()),
                        ("such buffers pass through untouched, with status=invalid-image"));
  }
  TrackResult r;
  r.status = TrackStatus::InvalidImage;
  r.detail = mapping.detail;
  r.inner_point = self->state->stream->tracker.inner_point();  // the track waits where it was
  return r;
}

// Logs a change of status, and warns of settings that conflict at once, whatever `updates` is,
// and again when they change.
void report_status(GstProjtrack* self, Stream& st, const TrackResult& r) {
  const std::string& detail = r.detail.empty() ? r.features.detail : r.detail;
  if (r.status != st.last_status) {
    GST_INFO_OBJECT(self, "status %s -> %s%s%s", status_name(st.last_status).data(),
                    status_name(r.status).data(), detail.empty() ? "" : ": ", detail.c_str());
    st.last_status = r.status;
  }
  if (r.status != TrackStatus::InvalidParameters) {
    st.last_warning.clear();
  } else if (detail != st.last_warning) {
    st.last_warning = detail;
    GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("Conflicting settings: %s", detail.c_str()),
                        ("nothing is tracked until they are fixed"));
  }
}

}  // namespace

// Per-stream state is made with the first caps. New caps of another size rescale the track (and
// the seeds given) to it; another format or colour range, at the same size, makes the tracker
// learn the object's colours anew: both keep the track.
gboolean set_info(GstVideoFilter* filter, GstCaps*, GstVideoInfo* in_info, GstCaps*,
                  GstVideoInfo*) {
  auto* self = GST_PROJTRACK(filter);
  // The objects' tracker is the application's threads' too (add-box, remove-object).
  std::unique_lock<std::mutex> objects_lock(self->state->objects_mutex);
  const bool first = !self->state->stream;
  if (first) {
    self->state->stream = std::make_unique<Stream>();
    self->state->stream->tracker.set_stop_flag(&self->state->interrupt);
    self->state->stream->objects.tracker.set_stop_flag(&self->state->interrupt);
  }
  Stream& st = *self->state->stream;
  const int width = GST_VIDEO_INFO_WIDTH(in_info), height = GST_VIDEO_INFO_HEIGHT(in_info);
  const GstVideoColorimetry& colours = in_info->colorimetry;
  st.layout_warnings.clear();
  const bool resized = !first && (width != st.width || height != st.height);
  const bool recoloured = !first && (GST_VIDEO_INFO_FORMAT(in_info) != st.format ||
                                     colours.range != st.range || colours.matrix != st.matrix);
  GST_OBJECT_LOCK(self);
  self->state->locked.frame_width = width;
  self->state->locked.frame_height = height;
  st.element_name = GST_OBJECT_NAME(self);  // for the metas: the name is fixed while streaming
  if (first)
    reseed_locked(self);
  else if (resized)
    rescale_seeds_locked(self, st.width, st.height, width, height);
  GST_OBJECT_UNLOCK(self);
  if (resized) {
    GST_DEBUG_OBJECT(self, "new frame size %dx%d -> %dx%d: the track is rescaled", st.width,
                     st.height, width, height);
    st.tracker.rescale(st.width, st.height, width, height);
    st.objects.tracker.rescale(st.width, st.height, width, height);
  } else if (recoloured) {
    GST_DEBUG_OBJECT(self, "new format %s: the object's colours are learned anew",
                     gst_video_format_to_string(GST_VIDEO_INFO_FORMAT(in_info)));
    st.tracker.relearn();
    st.objects.tracker.relearn();
  }
  st.width = width;
  st.height = height;
  st.format = GST_VIDEO_INFO_FORMAT(in_info);
  st.range = colours.range;
  st.matrix = colours.matrix;
  objects_lock.unlock();  // a notify handler may add an object
  if (resized) notify_inner_point(self);
  return TRUE;
}

gboolean stop(GstBaseTransform* trans) {
  auto* self = GST_PROJTRACK(trans);
  {
    std::lock_guard<std::mutex> objects_lock(self->state->objects_mutex);
    self->state->stream.reset();
  }
  GST_OBJECT_LOCK(self);
  reseed_locked(self);
  self->state->locked.restart_objects = true;  // the next stream starts from the lists again
  self->state->locked.tracked_x = self->state->locked.tracked_y = -1;
  GST_OBJECT_UNLOCK(self);
  return TRUE;
}

namespace {

// Warns of `note` (a seed refused or not applied): an element warning, never under the lock.
void warn_of_seed(GstProjtrack* self, const std::string& note) {
  if (!note.empty())
    GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("%s", note.c_str()),
                        ("the track in hand goes on; see the message's detail"));
}

// Warns of starts of start-boxes or start-points refused: an element warning each.
void warn_of_starts(GstProjtrack* self, const std::vector<std::string>& refused) {
  for (const std::string& why : refused)
    if (!why.empty())
      GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("%s", why.c_str()),
                          ("the other objects are followed; see docs/element.md"));
}

guint64 elapsed_ns(std::chrono::steady_clock::time_point start) {
  return static_cast<guint64>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start)
          .count());
}

// After the frame: the status logged and warned, the tracker's inner point published, and the
// message posted (after every lock is released), with `note` (a seed refused) in its detail.
void report(GstProjtrack* self, GstBuffer* buffer, const ElementSettings& s, const TrackResult& r,
            const FrameMapping& mapping, std::string note,
            std::chrono::steady_clock::time_point start) {
  Stream& st = *self->state->stream;
  report_status(self, st, r);
  if (r.gesture != Gesture::None)
    GST_INFO_OBJECT(self, "gesture: %s", gesture_name(r.gesture).data());
  const std::optional<Point2i>& inner = r.inner_point;
  GST_OBJECT_LOCK(self);
  self->state->locked.tracked_x = inner ? inner->x : -1;
  self->state->locked.tracked_y = inner ? inner->y : -1;
  GST_OBJECT_UNLOCK(self);
  if (!(s.post_messages && worth_posting(s.updates, r, st.last_posted))) return;
  const guint64 ns = elapsed_ns(start);
  const FrameReport frame{r,         s.method,   st.element_name.c_str(), st.track_id, st.width,
                          st.height, st.outline, std::move(note)};
  GstMessage* msg = result_message(self, buffer, frame, ns);
  if (!mapping.ok())
    gst_structure_set(gst_message_writable_structure(msg), "reason", G_TYPE_STRING, mapping.reason,
                      nullptr);
  gst_element_post_message(GST_ELEMENT(self), msg);  // never under the object lock
}

// The single track's metas and message, as they always were.
void report_single(GstProjtrack* self, GstBuffer* buffer, const ElementSettings& s,
                   const TrackResult& r, const FrameMapping& mapping, std::string note,
                   std::chrono::steady_clock::time_point start) {
  Stream& st = *self->state->stream;
  if (r.acquired) st.track_id = next_track_id();
  if (!mapping.ok()) st.outline.clear();
  if (has_features(r.status)) {
    const FrameReport frame_report{
        r, s.method, st.element_name.c_str(), st.track_id, st.width, st.height, st.outline, {}};
    attach_meta(buffer, frame_report);
  }
  report(self, buffer, s, r, mapping, std::move(note), start);
}

}  // namespace

// In place, as GstVideoFilter would, but the frame is mapped for writing only when the overlay
// draws or the alpha is written: a read-only map never copies a buffer that another branch (a
// tee) shares. A GAP buffer holds no picture: it passes on untouched, and the track waits.
GstFlowReturn transform_ip(GstBaseTransform* trans, GstBuffer* buffer) {
  auto* self = GST_PROJTRACK(trans);
  auto* filter = GST_VIDEO_FILTER(trans);
  if (!filter->negotiated || !self->state->stream) {
    GST_ELEMENT_ERROR(self, CORE, NEGOTIATION, (nullptr), ("no format negotiated"));
    return GST_FLOW_NOT_NEGOTIATED;
  }
  if (GST_BUFFER_FLAG_IS_SET(buffer, GST_BUFFER_FLAG_GAP)) {
    GST_LOG_OBJECT(self, "a GAP buffer: passed on untouched");
    return GST_FLOW_OK;
  }
  const auto start = std::chrono::steady_clock::now();

  GST_OBJECT_LOCK(self);
  const ElementSettings s = self->state->locked.settings;
  const SeedCommand command = std::exchange(self->state->locked.pending, SeedCommand::None);
  const bool restart = std::exchange(self->state->locked.restart_objects, false);
  std::string note = std::exchange(self->state->locked.seed_note, std::string());
  const std::string list_note = std::exchange(self->state->locked.objects_note, std::string());
  GST_OBJECT_UNLOCK(self);
  warn_of_seed(self, note);
  warn_of_starts(self, {list_note});

  const bool writes =
      s.draw || (s.alpha_mask && has_alpha(GST_VIDEO_INFO_FORMAT(&filter->in_info)));
  GstVideoFrame frame;
  const FrameMapping mapping = map_frame_checked(&frame, &filter->in_info, buffer,
                                                 writes ? GST_MAP_READWRITE : GST_MAP_READ);
  if (mapping.merged) GST_DEBUG_OBJECT(self, "a plane spanned memory blocks: merged them");
  FrameOutcome out;
  if (!mapping.ok()) out.single = unread_frame(self, mapping, command, restart);
  std::string not_applied;
  try {
    if (mapping.ok()) out = process(self, &frame, s, command, restart, not_applied);
  } catch (const std::exception& e) {  // e.g. std::bad_alloc: never unwind into GStreamer's C
    gst_video_frame_unmap(&frame);
    GST_ELEMENT_ERROR(self, STREAM, FAILED, ("Tracking failed: %s", e.what()), (nullptr));
    return GST_FLOW_ERROR;
  }
  if (mapping.ok()) gst_video_frame_unmap(&frame);
  warn_of_seed(self, not_applied);
  warn_of_starts(self, out.objects.refused);
  if (!not_applied.empty()) note += (note.empty() ? "" : "; ") + not_applied;

  if (out.single_ran) report_single(self, buffer, s, out.single, mapping, std::move(note), start);
  report_objects(self, buffer, s, out.objects, elapsed_ns(start));
  return GST_FLOW_OK;
}

}  // namespace projtrack::gst
