/* An application in C reads projtrack's features after videoconvert ! videoscale with nothing but
 * gstprojtrackmeta.h: compiled as C (the header is C), exit status 0 when every frame's meta is
 * there and scaled to 320×240. */
#include <gst/gst.h>
#include <math.h>
#include <stdio.h>

#include "gstprojtrackmeta.h"

static int frames, failures;

static void check(int ok, const char* what) {
  if (!ok) {
    fprintf(stderr, "FAIL frame %d: %s\n", frames, what);
    ++failures;
  }
}

static void on_buffer(GstElement* sink, GstBuffer* buffer, GstPad* pad, gpointer data) {
  const GstStructure* s = gst_buffer_get_projtrack_meta(buffer);
  GstProjtrackFeatures f;
  gint x, y;
  (void)sink;
  (void)pad;
  (void)data;
  check(gst_projtrack_features_read(s, &f), "a projtrack meta with every field");
  if (s && gst_projtrack_features_read(s, &f)) {
    check(f.frame_width == 320 && f.frame_height == 240, "the frame is 320x240");
    check(f.track_id > 0, "a track id");
    check(g_strcmp0(f.element, "tracker") == 0, "the element's name");
    check(f.area > 0 && f.area < 640 * 480 / 4.0, "an area in the small frame's pixels");
    check(f.x >= 0 && f.x + f.width <= 320 && f.y >= 0 && f.y + f.height <= 240,
          "the box in the frame");
    /* videotestsrc's ball starts at the centre: (320 + 0.5) / 2 - 0.5 */
    if (frames == 0)
      check(fabs(f.centroid_x - 159.75) < 2 && fabs(f.centroid_y - 119.75) < 2,
            "the first centroid at the small frame's centre");
    check(gst_projtrack_outline_n_polygons(s) >= 1, "an outline");
    check(gst_projtrack_outline_vertex(s, 0, 0, &x, &y) && x >= 0 && x < 320 && y >= 0 && y < 240,
          "its vertices in the frame");
  }
  ++frames;
}

int main(int argc, char** argv) {
  GstElement *pipeline, *sink;
  GstMessage* msg;
  gst_init(&argc, &argv);
  pipeline = gst_parse_launch(
      "videotestsrc pattern=ball animation-mode=frames num-buffers=10 "
      "! video/x-raw,format=I420,width=640,height=480 ! projtrack name=tracker "
      "inner-point-x=320 inner-point-y=240 ! videoconvert ! videoscale "
      "! video/x-raw,width=320,height=240 ! fakesink name=sink signal-handoffs=true",
      NULL);
  if (!pipeline) return 2;
  sink = gst_bin_get_by_name(GST_BIN(pipeline), "sink");
  g_signal_connect(sink, "handoff", G_CALLBACK(on_buffer), NULL);
  gst_object_unref(sink);
  gst_element_set_state(pipeline, GST_STATE_PLAYING);
  msg = gst_bus_timed_pop_filtered(GST_ELEMENT_BUS(pipeline), 20 * GST_SECOND,
                                   GST_MESSAGE_EOS | GST_MESSAGE_ERROR);
  check(msg && GST_MESSAGE_TYPE(msg) == GST_MESSAGE_EOS, "the pipeline ends");
  if (msg) gst_message_unref(msg);
  gst_element_set_state(pipeline, GST_STATE_NULL);
  gst_object_unref(pipeline);
  check(frames == 10, "every frame arrived");
  printf("%d frames, %d failures\n", frames, failures);
  return failures ? 1 : 0;
}
