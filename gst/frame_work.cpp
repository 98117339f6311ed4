#include "frame_work.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

#include "alpha_mask.hpp"
#include "frame_color.hpp"
#include "objects_overlay.hpp"
#include "overlay.hpp"
#include "projtrack/sample_clock.hpp"
#include "seeds.hpp"

namespace projtrack::gst {

namespace {

// Seconds for the smoothing and the push detector: the buffer's time, else the assumed rate.
double frame_time(Stream& st, GstBuffer* buffer) {
  const GstClockTime pts = GST_BUFFER_PTS(buffer);
  const double t = GST_CLOCK_TIME_IS_VALID(pts)
                       ? static_cast<double>(pts) / GST_SECOND
                       : static_cast<double>(st.frames) / kAssumedFrameRate;
  ++st.frames;
  return t;
}

// The single track runs as it always has, unless objects are followed at once and it was given
// no seed: then its automatic acquisition would only find one of them again, as a second track.
bool single_runs(const ElementSettings& s, const Objects& objects) {
  return objects.tracker.size() == 0 || (s.inner_point_x >= 0 && s.inner_point_y >= 0) ||
         !s.start_box.empty();
}

TrackResult track_single(GstProjtrack* self, Stream& st, const ColorView& color, double t,
                         const Settings& bundle, const ElementSettings& s) {
  // What the method did is recorded only when it is drawn (rays may number 131 072).
  const bool traced = s.draw && (s.draw_flags & (kDrawGrid | kDrawOutline));
  // The tracker computes the edges itself: while tracking, only around the object.
  TrackResult r = st.tracker.track(color, t, bundle, traced ? &st.trace : nullptr);
  const SilhouetteMask silhouette =
      has_features(r.status) ? st.tracker.silhouette() : SilhouetteMask{};
  st.outline = outline_polygons(silhouette);
  if (traced && st.trace.rays_not_recorded)
    GST_LOG_OBJECT(self, "overlay: %zu rays not recorded", st.trace.rays_not_recorded);
  return r;
}

// Whether alpha-ids chooses `id` (0: the single track) for the alpha.
bool cut_out(const ElementSettings& s, int id) {
  return s.alpha_ids.empty() ||
         std::find(s.alpha_ids.begin(), s.alpha_ids.end(), id) != s.alpha_ids.end();
}

// The alpha and the overlay, of the single track and of the objects (objects_mutex held: the
// objects' silhouettes are views into their tracker).
void write_outputs(GstVideoFrame* frame, const ElementSettings& s, Stream& st,
                   const FrameOutcome& out) {
  if (s.alpha_mask && has_alpha(GST_VIDEO_FRAME_FORMAT(frame))) {
    std::vector<SilhouetteMask> cut;
    if (out.single_ran && has_features(out.single.status) && cut_out(s, 0))
      cut.push_back(st.tracker.silhouette());
    for (const TrackResult& r : out.objects.results)
      if (has_features(r.status) && cut_out(s, r.id))
        cut.push_back(st.objects.tracker.silhouette(r.id));
    write_alpha(frame, cut);
  }
  if (!s.draw) return;
  if (out.single_ran) draw_overlay(frame, s.method, out.single, st.trace, s.draw_flags);
  draw_objects(frame, out.objects, s.draw_flags);
}

}  // namespace

FrameOutcome process(GstProjtrack* self, GstVideoFrame* frame, const ElementSettings& s,
                     SeedCommand command, bool restart, std::string& note) {
  Stream& st = *self->state->stream;
  note = apply_seed(st.tracker, command, s, st.width, st.height);
  Settings bundle = s;  // the library's part of the element's settings
  // frame_color() gives every frame at video range: an edge map's black is 16 there.
  bundle.edges.input_black_level = kVideoBlack;
  const ColorView color = frame_color(frame, st.converted);
  const double t = frame_time(st, frame->buffer);
  FrameOutcome out;
  std::lock_guard<std::mutex> objects_lock(self->state->objects_mutex);
  out.objects = track_objects(st.objects, color, t, bundle, s, restart, st.width, st.height);
  out.single_ran = single_runs(s, st.objects);
  if (out.single_ran) out.single = track_single(self, st, color, t, bundle, s);
  write_outputs(frame, s, st, out);
  return out;
}

}  // namespace projtrack::gst
