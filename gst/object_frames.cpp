#include "object_frames.hpp"

#include "objects.hpp"
#include "results.hpp"

namespace projtrack::gst {

ObjectsFrame track_objects(Objects& objects, const ColorView& color, double t,
                           const Settings& bundle, const ElementSettings& s, bool restart,
                           int width, int height) {
  ObjectsFrame out;
  if (restart) out.refused = restart_objects(objects, s, width, height);
  if (objects.tracker.size() == 0) return out;
  out.results = objects.tracker.track(color, t, bundle);
  for (const TrackResult& r : out.results) {
    int& track_id = objects.track_ids[r.id];
    if (r.acquired || track_id == 0) track_id = next_track_id();
    out.track_ids.push_back(track_id);
    out.outlines.push_back(has_features(r.status)
                               ? outline_polygons(objects.tracker.silhouette(r.id))
                               : std::vector<std::vector<Point2i>>{});
    out.posts.push_back(s.post_messages && worth_posting(s.updates, r, objects.last_posted[r.id]));
  }
  return out;
}

void report_objects(GstProjtrack* self, GstBuffer* buffer, const ElementSettings& s,
                    const ObjectsFrame& frame, guint64 processing_ns) {
  const Stream& st = *self->state->stream;
  for (std::size_t i = 0; i < frame.results.size(); ++i) {
    const TrackResult& r = frame.results[i];
    const FrameReport report{r,        s.method,  st.element_name.c_str(), frame.track_ids[i],
                             st.width, st.height, frame.outlines[i],       {}};
    if (has_features(r.status)) attach_meta(buffer, report);
    if (frame.posts[i])
      gst_element_post_message(GST_ELEMENT(self),
                               result_message(self, buffer, report, processing_ns));
  }
}

}  // namespace projtrack::gst
