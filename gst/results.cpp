#include "results.hpp"

#include <gst/base/gstbasetransform.h>
#include <gst/video/video.h>

#include <atomic>

#include "meta.hpp"

namespace projtrack::gst {

namespace {

// The outline as a GstValueArray of polygons, each a GstValueArray of ints x0, y0, x1, y1, ...
void set_outline(GstStructure* s, const std::vector<std::vector<Point2i>>& outline) {
  GValue polygons = G_VALUE_INIT;
  gst_value_array_init(&polygons, outline.size());
  for (const std::vector<Point2i>& polygon : outline) {
    GValue points = G_VALUE_INIT;
    gst_value_array_init(&points, 2 * polygon.size());
    for (const Point2i& p : polygon)
      for (int v : {p.x, p.y}) {
        GValue c = G_VALUE_INIT;
        g_value_init(&c, G_TYPE_INT);
        g_value_set_int(&c, v);
        gst_value_array_append_and_take_value(&points, &c);
      }
    gst_value_array_append_and_take_value(&polygons, &points);
  }
  gst_structure_take_value(s, "outline", &polygons);
}

// The features, the pose and the status: the metas' fields and the message's core.
GstStructure* result_structure(const FrameReport& report) {
  const TrackResult& r = report.result;
  GstStructure* s = gst_structure_new(
      "projtrack", "status", G_TYPE_STRING, status_name(r.status).data(), "method", G_TYPE_STRING,
      method_name(report.method).data(), "element", G_TYPE_STRING, report.element, "frame-width",
      G_TYPE_INT, report.width, "frame-height", G_TYPE_INT, report.height, nullptr);
  // An object followed among several has its id (from 1); the single track's fields stay as
  // they always were, without one.
  if (r.id > 0) gst_structure_set(s, "id", G_TYPE_INT, r.id, nullptr);
  const Features& f = r.features;
  if (f.valid()) {  // when lost: the last accepted features
    if (report.track_id > 0) gst_structure_set(s, "track-id", G_TYPE_INT, report.track_id, nullptr);
    gst_structure_set(s, "centroid-x", G_TYPE_DOUBLE, f.centroid.x, "centroid-y", G_TYPE_DOUBLE,
                      f.centroid.y, "area", G_TYPE_DOUBLE, f.area, "x", G_TYPE_INT, f.bbox.x, "y",
                      G_TYPE_INT, f.bbox.y, "width", G_TYPE_INT, f.bbox.width, "height", G_TYPE_INT,
                      f.bbox.height, "inner-point-x", G_TYPE_INT, f.inner_point.x, "inner-point-y",
                      G_TYPE_INT, f.inner_point.y, "iterations", G_TYPE_INT, f.iterations, nullptr);
  }
  if (r.has_pose) {
    gst_structure_set(s, "position-x", G_TYPE_DOUBLE, r.pose.x, "position-y", G_TYPE_DOUBLE,
                      r.pose.y, "depth", G_TYPE_DOUBLE, r.pose.depth, nullptr);
  }
  // push, press or release, on the frame it completed (a release also when the track ended)
  if (r.gesture != Gesture::None)
    gst_structure_set(s, "gesture", G_TYPE_STRING, gesture_name(r.gesture).data(), nullptr);
  if (has_features(r.status)) set_outline(s, report.outline);
  return s;
}

}  // namespace

int next_track_id() {
  static std::atomic<int> last{0};
  int id = last.load(), next = 0;
  do {
    next = id >= G_MAXINT - 1 ? 1 : id + 1;  // never 0 (no track) or negative
  } while (!last.compare_exchange_weak(id, next));
  return next;
}

void attach_meta(GstBuffer* buffer, const FrameReport& report) {
  const Rect& b = report.result.features.bbox;
  GstVideoRegionOfInterestMeta* roi =
      gst_buffer_add_video_region_of_interest_meta(buffer, "object", b.x, b.y, b.width, b.height);
  roi->id = report.result.id > 0 ? report.result.id : report.track_id;
  GstStructure* features = result_structure(report);
  // The ROI meta's parameters do not survive videoscale in GStreamer 1.22 (its transform drops
  // them): GstProjtrackMeta carries the same fields through.
  add_projtrack_meta(buffer, features);
  gst_video_region_of_interest_meta_add_param(roi, features);
}

GstMessage* result_message(GstProjtrack* self, GstBuffer* buffer, const FrameReport& report,
                           guint64 processing_ns) {
  const TrackResult& r = report.result;
  const GstSegment* segment = &GST_BASE_TRANSFORM(self)->segment;
  const GstClockTime pts = GST_BUFFER_PTS(buffer);
  const GstClockTime stream_time = gst_segment_to_stream_time(segment, GST_FORMAT_TIME, pts);
  const GstClockTime running_time = gst_segment_to_running_time(segment, GST_FORMAT_TIME, pts);
  GstStructure* s = result_structure(report);
  const Features& f = r.features;
  if (f.valid()) {
    gst_structure_set(s, "rays-cast", G_TYPE_UINT64, static_cast<guint64>(f.rays_cast),
                      "pixels-visited", G_TYPE_UINT64, static_cast<guint64>(f.pixels_visited),
                      nullptr);
  } else if (const std::optional<Point2i>& inner = r.inner_point) {
    gst_structure_set(s, "inner-point-x", G_TYPE_INT, inner->x, "inner-point-y", G_TYPE_INT,
                      inner->y, nullptr);
  }
  std::string detail = r.detail.empty() ? f.detail : r.detail;
  if (!report.note.empty()) detail = report.note + (detail.empty() ? "" : "; " + detail);
  if (!detail.empty()) gst_structure_set(s, "detail", G_TYPE_STRING, detail.c_str(), nullptr);
  if (r.acquired) gst_structure_set(s, "acquired", G_TYPE_BOOLEAN, TRUE, nullptr);
  gst_structure_set(s, "timestamp", G_TYPE_UINT64, pts, "stream-time", G_TYPE_UINT64, stream_time,
                    "running-time", G_TYPE_UINT64, running_time, "duration", G_TYPE_UINT64,
                    GST_BUFFER_DURATION(buffer), "processing-time", G_TYPE_UINT64, processing_ns,
                    "work", G_TYPE_UINT64, static_cast<guint64>(r.work), nullptr);
  return gst_message_new_element(GST_OBJECT(self), s);
}

bool worth_posting(Updates updates, const TrackResult& r, std::optional<TrackStatus>& last) {
  const bool changed = last != r.status || r.acquired || r.gesture != Gesture::None;
  last = r.status;
  return updates == Updates::EveryFrame || (updates == Updates::OnChange && changed);
}

}  // namespace projtrack::gst
