/* Prints the centroid and area that projtrack measures on every frame, from C.
 *
 *   GST_PLUGIN_PATH=build/gst build/examples/print_features [pipeline]
 *
 * The pipeline (default: videotestsrc's ball) must contain a projtrack element; its "projtrack"
 * element messages are read from the bus. docs/element.md lists every field. */
#include <gst/gst.h>
#include <stdio.h>

#define DEFAULT_PIPELINE                                                           \
  "videotestsrc pattern=ball num-buffers=60 ! video/x-raw,width=320,height=240 ! " \
  "projtrack inner-point-x=160 inner-point-y=120 ! fakesink"

/* Only these statuses carry features measured on this frame; a "lost" message repeats the last
 * measured ones, which must not be read as a measurement. */
static gboolean measured(const gchar* status) {
  return g_strcmp0(status, "ok") == 0 || g_strcmp0(status, "reached-border") == 0 ||
         g_strcmp0(status, "covers-frame") == 0;
}

static void print_features(const GstStructure* s) {
  GstClockTime ts = GST_CLOCK_TIME_NONE;
  gdouble cx = 0, cy = 0, area = 0;
  gst_structure_get_uint64(s, "timestamp", &ts);
  const gchar* status = gst_structure_get_string(s, "status");
  if (measured(status) && gst_structure_get_double(s, "centroid-x", &cx) &&
      gst_structure_get_double(s, "centroid-y", &cy) &&
      gst_structure_get_double(s, "area", &area)) {
    printf("%" GST_TIME_FORMAT " %-15s centroid (%7.1f, %7.1f)  area %9.0f px²\n",
           GST_TIME_ARGS(ts), status, cx, cy, area);
  } else { /* nothing measured: the status says why */
    const gchar* detail = gst_structure_get_string(s, "detail");
    printf("%" GST_TIME_FORMAT " %-15s %s\n", GST_TIME_ARGS(ts), status, detail ? detail : "");
  }
}

int main(int argc, char** argv) {
  GError* error = NULL;
  gst_init(&argc, &argv);
  GstElement* pipeline = gst_parse_launch(argc > 1 ? argv[1] : DEFAULT_PIPELINE, &error);
  if (!pipeline) {
    g_printerr("cannot build the pipeline: %s\n", error->message);
    g_clear_error(&error);
    return 1;
  }
  GstBus* bus = gst_element_get_bus(pipeline);
  gst_element_set_state(pipeline, GST_STATE_PLAYING);
  int code = 0;
  for (gboolean done = FALSE; !done;) {
    GstMessage* msg = gst_bus_timed_pop_filtered(
        bus, GST_CLOCK_TIME_NONE, GST_MESSAGE_ELEMENT | GST_MESSAGE_EOS | GST_MESSAGE_ERROR);
    switch (GST_MESSAGE_TYPE(msg)) {
      case GST_MESSAGE_ELEMENT:
        if (gst_message_has_name(msg, "projtrack")) print_features(gst_message_get_structure(msg));
        break;
      case GST_MESSAGE_ERROR:
        gst_message_parse_error(msg, &error, NULL);
        g_printerr("error: %s\n", error->message);
        g_clear_error(&error);
        code = 1;
        done = TRUE;
        break;
      default: /* end of stream */
        done = TRUE;
        break;
    }
    gst_message_unref(msg);
  }
  gst_element_set_state(pipeline, GST_STATE_NULL);
  gst_object_unref(bus);
  gst_object_unref(pipeline);
  return code;
}
