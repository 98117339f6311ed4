/* Prints the centroid and area that projtrack measures on every frame, from C.
 *
 *   GST_PLUGIN_PATH=build/gst build/examples/print_features [--help] [PIPELINE]
 *
 * The pipeline (default: videotestsrc's ball) must contain a projtrack element; its "projtrack"
 * element messages are read from the bus. docs/element.md lists every field. Exit code 0 at the
 * end of the stream, 1 on a pipeline error, 2 for bad arguments or a pipeline that cannot be
 * built. */
#include <getopt.h>
#include <gst/gst.h>
#include <stdio.h>

#define DEFAULT_PIPELINE                                                           \
  "videotestsrc pattern=ball num-buffers=60 ! video/x-raw,width=320,height=240 ! " \
  "projtrack inner-point-x=160 inner-point-y=120 ! fakesink"

enum { EXIT_OK = 0, EXIT_FAILED = 1, EXIT_USAGE = 2 };

static void usage(FILE* to) {
  fprintf(to,
          "usage: print_features [-h] [PIPELINE]\n\n"
          "Prints the centroid and area that projtrack measures on every frame.\n\n"
          "positional arguments:\n"
          "  PIPELINE    a gst-launch-1.0 pipeline with a projtrack element\n"
          "              (default: videotestsrc's ball)\n\n"
          "options:\n"
          "  -h, --help  show this help message and exit\n");
}

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
  fflush(stdout);
}

/* Whether `bin` holds a projtrack element, at any depth. */
static gboolean has_projtrack(GstBin* bin) {
  GstIterator* it = gst_bin_iterate_recurse(bin);
  GValue item = G_VALUE_INIT;
  gboolean found = FALSE;
  while (!found && gst_iterator_next(it, &item) == GST_ITERATOR_OK) {
    GstElementFactory* f = gst_element_get_factory(GST_ELEMENT(g_value_get_object(&item)));
    found = f && g_strcmp0(gst_plugin_feature_get_name(GST_PLUGIN_FEATURE(f)), "projtrack") == 0;
    g_value_reset(&item);
  }
  g_value_unset(&item);
  gst_iterator_free(it);
  return found;
}

/* The pipeline `description` says, always a GstPipeline (one element alone is put in one, to
 * have a bus); NULL, with the reason printed, when it cannot be built. */
static GstElement* build_pipeline(const char* description) {
  GError* error = NULL;
  GstElement* e = gst_parse_launch_full(description, NULL, GST_PARSE_FLAG_FATAL_ERRORS, &error);
  if (!e || error) {
    g_printerr("print_features: cannot build the pipeline: %s\n",
               error ? error->message : "unknown error");
    g_clear_error(&error);
    if (e) gst_object_unref(e);
    return NULL;
  }
  if (!GST_IS_PIPELINE(e)) {
    GstElement* pipeline = gst_pipeline_new(NULL);
    gst_bin_add(GST_BIN(pipeline), e);
    e = pipeline;
  }
  if (!has_projtrack(GST_BIN(e))) {
    g_printerr("print_features: the pipeline has no projtrack element\n");
    gst_object_unref(e);
    return NULL;
  }
  return e;
}

/* Prints every projtrack message until the end of the stream: EXIT_OK, or EXIT_FAILED on an
 * error (printed). */
static int print_messages(GstBus* bus) {
  for (;;) {
    GstMessage* msg = gst_bus_timed_pop_filtered(
        bus, GST_CLOCK_TIME_NONE, GST_MESSAGE_ELEMENT | GST_MESSAGE_EOS | GST_MESSAGE_ERROR);
    const GstMessageType type = GST_MESSAGE_TYPE(msg);
    if (type == GST_MESSAGE_ELEMENT && gst_message_has_name(msg, "projtrack"))
      print_features(gst_message_get_structure(msg));
    if (type == GST_MESSAGE_ERROR) {
      GError* error = NULL;
      gst_message_parse_error(msg, &error, NULL);
      g_printerr("print_features: pipeline error: %s: %s\n", GST_OBJECT_NAME(msg->src),
                 error->message);
      g_clear_error(&error);
    }
    gst_message_unref(msg);
    if (type == GST_MESSAGE_ERROR) return EXIT_FAILED;
    if (type == GST_MESSAGE_EOS) return EXIT_OK;
  }
}

int main(int argc, char** argv) {
  gst_init(&argc, &argv); /* takes GStreamer's own options (--gst-debug=...) out of argv */
  static const struct option options[] = {{"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
  for (int c; (c = getopt_long(argc, argv, "h", options, NULL)) != -1;) {
    if (c == 'h') {
      usage(stdout);
      return EXIT_OK;
    }
    usage(stderr);
    return EXIT_USAGE;
  }
  if (argc - optind > 1) {
    usage(stderr);
    g_printerr("print_features: one pipeline expected (quote it), %d arguments given\n",
               argc - optind);
    return EXIT_USAGE;
  }
  GstElementFactory* projtrack = gst_element_factory_find("projtrack");
  if (!projtrack) {
    g_printerr(
        "print_features: no projtrack element: point GST_PLUGIN_PATH at the build's "
        "plugin (GST_PLUGIN_PATH=$PWD/build/gst) or install it\n");
    return EXIT_USAGE;
  }
  gst_object_unref(projtrack);
  GstElement* pipeline = build_pipeline(optind < argc ? argv[optind] : DEFAULT_PIPELINE);
  if (!pipeline) return EXIT_USAGE;
  GstBus* bus = gst_element_get_bus(pipeline);
  int code = EXIT_FAILED;
  if (gst_element_set_state(pipeline, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE) {
    GstMessage* msg = gst_bus_pop_filtered(bus, GST_MESSAGE_ERROR);
    GError* error = NULL;
    if (msg) gst_message_parse_error(msg, &error, NULL);
    g_printerr("print_features: the pipeline cannot start%s%s\n", error ? ": " : "",
               error ? error->message : "");
    g_clear_error(&error);
    if (msg) gst_message_unref(msg);
  } else {
    code = print_messages(bus);
  }
  gst_element_set_state(pipeline, GST_STATE_NULL);
  gst_object_unref(bus);
  gst_object_unref(pipeline);
  return code;
}
