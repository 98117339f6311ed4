// Each buffer: the settings copied under the lock, the frame mapped after its layout is checked,
// the tracker run, the meta attached, the status logged and warned, and the message posted after
// the lock is released.
#include "stream.hpp"

#include <chrono>
#include <exception>
#include <optional>
#include <string>
#include <utility>

#include "element.hpp"
#include "frame_color.hpp"
#include "frame_mapping.hpp"
#include "overlay.hpp"
#include "projtrack/sample_clock.hpp"
#include "results.hpp"
#include "seeds.hpp"

namespace projtrack::gst {

namespace {

// Runs edges + estimator on one mapped frame, and draws when asked.
TrackResult process(GstProjtrack* self, GstVideoFrame* frame, const Settings& s,
                    SeedCommand command) {
  Stream& st = *self->stream;
  if (command == SeedCommand::Seed)
    st.tracker.seed({s.seed_x, s.seed_y});
  else if (command == SeedCommand::SeedBox)
    st.tracker.seed_box(s.seed_box);
  else if (command == SeedCommand::Reset)
    st.tracker.reset();
  EdgeParams edge_params = s.edges;
  edge_params.input_black_level = st.black_level;
  const ColorView color = frame_color(frame, st.converted);
  Trace* trace = s.draw ? &st.trace : nullptr;
  // Seconds for the smoothing and the push detector: the buffer's time, else the assumed rate.
  const GstClockTime pts = GST_BUFFER_PTS(frame->buffer);
  const double t = GST_CLOCK_TIME_IS_VALID(pts)
                       ? static_cast<double>(pts) / GST_SECOND
                       : static_cast<double>(st.frames) / kAssumedFrameRate;
  ++st.frames;
  // The tracker computes the edges itself: while tracking, only around the object.
  TrackResult r = st.tracker.track(color, edge_params, t, s.method, s.params, s.tracker, trace);
  if (s.draw) {
    draw_overlay(frame, s.method, r, st.trace);
    if (st.trace.rays_not_recorded)
      GST_LOG_OBJECT(self, "overlay: %zu rays not recorded", st.trace.rays_not_recorded);
  }
  return r;
}

// A buffer whose layout does not fit its memory is not read: it passes through untouched, the
// track waits (a seed given meanwhile applies to the next readable frame), and the status says
// why. One element warning per reason and caps; the debug log has every frame.
TrackResult unread_frame(GstProjtrack* self, const FrameMapping& mapping, SeedCommand command) {
  GST_OBJECT_LOCK(self);
  if (self->pending == SeedCommand::None) self->pending = command;
  GST_OBJECT_UNLOCK(self);
  GST_DEBUG_OBJECT(self, "buffer not read (%s): %s", mapping.reason, mapping.detail.c_str());
  if (self->stream->layout_warnings.insert(mapping.reason).second) {
    GST_ELEMENT_WARNING(self, STREAM, FORMAT,
                        ("Video buffer not read (%s): %s", mapping.reason, mapping.detail.c_str()),
                        ("such buffers pass through untouched, with status=invalid-image"));
  }
  TrackResult r;
  r.status = TrackStatus::InvalidImage;
  r.detail = mapping.detail;
  r.inner_point = self->stream->tracker.inner_point();  // the track waits where it was
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

gboolean set_info(GstVideoFilter* filter, GstCaps*, GstVideoInfo* in_info, GstCaps*,
                  GstVideoInfo*) {
  auto* self = GST_PROJTRACK(filter);
  if (!self->stream) {
    self->stream = new Stream;
    self->stream->tracker.set_stop_flag(self->interrupt);
  }
  Stream& st = *self->stream;
  const int width = GST_VIDEO_INFO_WIDTH(in_info), height = GST_VIDEO_INFO_HEIGHT(in_info);
  st.black_level =
      GST_VIDEO_INFO_IS_YUV(in_info) && in_info->colorimetry.range == GST_VIDEO_COLOR_RANGE_16_235
          ? 16
          : 0;
  st.layout_warnings.clear();
  GST_OBJECT_LOCK(self);
  self->frame_width = width;
  self->frame_height = height;
  if (width != st.width || height != st.height) reseed_locked(self);
  GST_OBJECT_UNLOCK(self);
  if (width != st.width || height != st.height) {
    GST_DEBUG_OBJECT(self, "new frame size %dx%d: the track restarts", width, height);
    st.tracker.reset();
    st.width = width;
    st.height = height;
  }
  return TRUE;
}

gboolean stop(GstBaseTransform* trans) {
  auto* self = GST_PROJTRACK(trans);
  delete self->stream;
  self->stream = nullptr;
  GST_OBJECT_LOCK(self);
  reseed_locked(self);
  self->tracked_x = self->tracked_y = -1;
  GST_OBJECT_UNLOCK(self);
  return TRUE;
}

// In place, as GstVideoFilter would, but the frame is mapped for writing only when the overlay
// draws: a read-only map never copies a buffer that another branch (a tee) shares.
GstFlowReturn transform_ip(GstBaseTransform* trans, GstBuffer* buffer) {
  auto* self = GST_PROJTRACK(trans);
  auto* filter = GST_VIDEO_FILTER(trans);
  if (!filter->negotiated || !self->stream) {
    GST_ELEMENT_ERROR(self, CORE, NEGOTIATION, (nullptr), ("no format negotiated"));
    return GST_FLOW_NOT_NEGOTIATED;
  }
  const auto start = std::chrono::steady_clock::now();

  GST_OBJECT_LOCK(self);
  const Settings s = *self->settings;
  const SeedCommand command = std::exchange(self->pending, SeedCommand::None);
  GST_OBJECT_UNLOCK(self);

  GstVideoFrame frame;
  const FrameMapping mapping = map_frame_checked(&frame, &filter->in_info, buffer,
                                                 s.draw ? GST_MAP_READWRITE : GST_MAP_READ);
  if (mapping.merged) GST_DEBUG_OBJECT(self, "a plane spanned memory blocks: merged them");
  TrackResult r = mapping.ok() ? TrackResult{} : unread_frame(self, mapping, command);
  try {
    if (mapping.ok()) r = process(self, &frame, s, command);
  } catch (const std::exception& e) {  // e.g. std::bad_alloc: never unwind into GStreamer's C
    gst_video_frame_unmap(&frame);
    GST_ELEMENT_ERROR(self, STREAM, FAILED, ("Tracking failed: %s", e.what()), (nullptr));
    return GST_FLOW_ERROR;
  }
  if (mapping.ok()) gst_video_frame_unmap(&frame);
  if (has_features(r.status)) attach_meta(buffer, r, s.method);

  Stream& st = *self->stream;
  report_status(self, st, r);
  if (r.gesture != Gesture::None)
    GST_INFO_OBJECT(self, "gesture: %s", gesture_name(r.gesture).data());
  const std::optional<Point2i>& inner = r.inner_point;
  GST_OBJECT_LOCK(self);
  self->tracked_x = inner ? inner->x : -1;
  self->tracked_y = inner ? inner->y : -1;
  GST_OBJECT_UNLOCK(self);

  if (s.post_messages && worth_posting(s.updates, r, st.last_posted)) {
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                        std::chrono::steady_clock::now() - start)
                        .count();
    GstMessage* msg = result_message(self, buffer, r, s.method, static_cast<guint64>(ns));
    if (!mapping.ok())
      gst_structure_set(gst_message_writable_structure(msg), "reason", G_TYPE_STRING,
                        mapping.reason, nullptr);
    gst_element_post_message(GST_ELEMENT(self), msg);  // never under the object lock
  }
  return GST_FLOW_OK;
}

}  // namespace projtrack::gst
