#include "results.hpp"

#include <gst/base/gstbasetransform.h>
#include <gst/video/video.h>

#include <string>

namespace projtrack::gst {

namespace {

// The features, the pose and the status: the ROI meta's parameters and the message's core.
GstStructure* result_structure(const TrackResult& r, Method method) {
  GstStructure* s =
      gst_structure_new("projtrack", "status", G_TYPE_STRING, status_name(r.status).data(),
                        "method", G_TYPE_STRING, method_name(method).data(), nullptr);
  const Features& f = r.features;
  if (f.valid()) {  // when lost: the last accepted features
    gst_structure_set(s, "centroid-x", G_TYPE_DOUBLE, f.centroid.x, "centroid-y", G_TYPE_DOUBLE,
                      f.centroid.y, "area", G_TYPE_DOUBLE, f.area, "inner-point-x", G_TYPE_INT,
                      f.inner_point.x, "inner-point-y", G_TYPE_INT, f.inner_point.y, "iterations",
                      G_TYPE_INT, f.iterations, nullptr);
  }
  if (r.has_pose) {
    gst_structure_set(s, "position-x", G_TYPE_DOUBLE, r.pose.x, "position-y", G_TYPE_DOUBLE,
                      r.pose.y, "depth", G_TYPE_DOUBLE, r.pose.depth, nullptr);
  }
  // push, press or release, on the frame it completed (a release also when the track ended)
  if (r.gesture != Gesture::None)
    gst_structure_set(s, "gesture", G_TYPE_STRING, gesture_name(r.gesture).data(), nullptr);
  return s;
}

}  // namespace

void attach_meta(GstBuffer* buffer, const TrackResult& r, Method method) {
  const Rect& b = r.features.bbox;
  GstVideoRegionOfInterestMeta* meta =
      gst_buffer_add_video_region_of_interest_meta(buffer, "object", b.x, b.y, b.width, b.height);
  gst_video_region_of_interest_meta_add_param(meta, result_structure(r, method));
}

GstMessage* result_message(GstProjtrack* self, GstBuffer* buffer, const TrackResult& r,
                           Method method, guint64 processing_ns) {
  const GstSegment* segment = &GST_BASE_TRANSFORM(self)->segment;
  const GstClockTime pts = GST_BUFFER_PTS(buffer);
  const GstClockTime stream_time = gst_segment_to_stream_time(segment, GST_FORMAT_TIME, pts);
  const GstClockTime running_time = gst_segment_to_running_time(segment, GST_FORMAT_TIME, pts);
  GstStructure* s = result_structure(r, method);
  const Features& f = r.features;
  if (f.valid()) {
    gst_structure_set(s, "x", G_TYPE_INT, f.bbox.x, "y", G_TYPE_INT, f.bbox.y, "width", G_TYPE_INT,
                      f.bbox.width, "height", G_TYPE_INT, f.bbox.height, "rays-cast", G_TYPE_UINT64,
                      static_cast<guint64>(f.rays_cast), "pixels-visited", G_TYPE_UINT64,
                      static_cast<guint64>(f.pixels_visited), nullptr);
  } else if (const std::optional<Point2i>& inner = r.inner_point) {
    gst_structure_set(s, "inner-point-x", G_TYPE_INT, inner->x, "inner-point-y", G_TYPE_INT,
                      inner->y, nullptr);
  }
  const std::string& detail = r.detail.empty() ? f.detail : r.detail;
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
