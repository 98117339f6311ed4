/**
 * SECTION:element-projtrack
 * @title: projtrack
 *
 * Tracks one object in video from a point inside it (the *inner point*), a box around it or by
 * itself, with the estimators of Quesada & León, "Filling-Based Techniques Applied to Object
 * Projection Feature Estimation", or with ours beyond the paper, gap-tolerant filling (the
 * default method): on every buffer it reports the object's centroid, area (px²) and bounding box.
 *
 * With `object-model=flow` (the default) it follows the whole object: its last silhouette is
 * carried along the picture's dense motion and cut from its surroundings by the colours (chroma
 * read from the frame's own planes) and the motion of both, so that a real object is tracked
 * through its prints, highlights and turns, and the estimator runs on that silhouette's outline.
 * `object-model=edges` is the paper's tracker alone: the estimator on the edge image from the
 * inner point.
 *
 * While tracking, every buffer carries a #GstVideoRegionOfInterestMeta of type `object` (the
 * bounding box; its id is the track's `track-id`, new on every acquisition) with a `projtrack`
 * parameter structure holding the features, and a `GstProjtrackMeta` (a #GstCustomMeta, read
 * with gstprojtrackmeta.h from C, buffer.get_custom_meta() from Python) holding them too, the
 * element's name and the silhouette's outline: its transform scales them through videoconvert and
 * videoscale, where GStreamer 1.22 drops the ROI meta's parameters. The element posts an element
 * message named `projtrack` (see docs/element.md for every field). Without an object the
 * message's `status` says why (e.g. `no-inner-point`) and no meta is attached. With
 * `alpha-mask=true` and a format with alpha (AYUV, A420, BGRA...), the silhouette is written
 * into the alpha channel, so that compositor shows the object alone.
 *
 * Without an inner point (`acquisition=auto`, the default) it finds the moving object itself, and
 * finds it again after losing it: an estimate whose area leaks or collapses is refused and
 * reported as `status=lost` with the last good features. Every tracked frame carries a 3D
 * pointer: `position-x`, `position-y` in [-1, 1] and a relative `depth` (smoothed by a One Euro
 * filter), and moving it toward the camera posts `gesture=push` (a click), `press` and
 * `release` (a drag).
 *
 * An inner point or a box can also be given: the `inner-point-x`/`inner-point-y` and
 * `start-box` properties, the `track-point`, `track-box` and `reset` action signals (one call, no
 * race), or a click: a left mouse-button press arriving from downstream (a click in the window of
 * `autovideosink`) starts tracking at the clicked pixel; a right click stops it.
 * `current-inner-point-x`/`-y` say where the tracker is. `updates` chooses which frames post a
 * message (every frame, on a change, none); conflicting settings are posted as an element warning
 * and `status=invalid-parameters` on the first frame, a malformed box as an element warning and
 * the next message's `detail`. With `draw=true` the element draws the status and why, x, y and
 * depth, the object's outline and what the estimator did (`draw-flags` chooses which). New caps
 * of another size rescale the track, another format keeps it; a flush restarts it from the point
 * or box given; GAP buffers pass untouched. Numeric settings may be driven by a #GstController.
 *
 * It follows several objects at once too, each with an id of its own (from 1), beside the single
 * track above, which stays as it is: `start-boxes` and `start-points` (lists of boxes and points),
 * the `add-box` and `add-point` action signals (which return the new id, 0 when refused with a
 * warning) and `remove-object`, or a click with `click-adds=true`; at most `max-objects`. Each
 * object gets its own ROI meta (its `id` the object's), GstProjtrackMeta and message, with an `id`
 * field; the overlay draws each in its colour with its id, and `alpha-mask` cuts out all of them or
 * those `alpha-ids` lists.
 *
 * No frame can stall the pipeline: each has a budget of work (`max-work`, in passes over its
 * pixels, counted in work and never in time) that every stage spends from — the flow model's
 * before each of its stages runs, edge detection and every estimate as they go; a frame that runs
 * out ends with `status=over-budget` and counts as a refused one. A state change
 * to READY or NULL, or a flush, stops a frame in progress (`status=interrupted`), so
 * gst_element_set_state() never waits for a long frame.
 *
 * YUV formats (GRAY8, I420, YV12, NV12, NV21, Y42B, Y444, A420) are read in place, luma and
 * chroma; YUY2, UYVY and AYUV have their chroma read in place and their luma gathered once; packed
 * RGB is converted internally. The element works in place; without `draw` it maps frames
 * read-only and never copies them.
 *
 * ## Example launch lines
 * |[
 * gst-launch-1.0 -m videotestsrc pattern=ball num-buffers=100 ! video/x-raw,width=320,height=240 !
 * projtrack inner-point-x=160 inner-point-y=120 ! fakesink
 * ]| Tracks videotestsrc's ball and prints a `projtrack` message per frame.
 * |[
 * gst-launch-1.0 -m v4l2src ! videoconvert ! projtrack draw=true updates=on-change ! videoconvert !
 * autovideosink
 * ]| Move an object in view: it is found, tracked and, when lost, found again by its colours;
 * clicking on an object tracks that one. The overlay says what is tracked, or why not; a message is
 * posted only when that changes.
 * |[
 * gst-launch-1.0 filesrc location=clip.mp4 ! decodebin ! videoconvert ! projtrack
 * method=pixel-filling draw=true inner-point-x=320 inner-point-y=240 ! videoconvert ! autovideosink
 * ]| Tracks from a given inner point in a file, with pixel-filling.
 * |[
 * gst-launch-1.0 compositor name=c ! videoconvert ! autovideosink videotestsrc pattern=smpte !
 * video/x-raw,width=320,height=240 ! c.sink_0 videotestsrc pattern=ball ! video/x-raw,format=BGRA,
 * width=320,height=240 ! projtrack inner-point-x=160 inner-point-y=120 alpha-mask=true ! c.sink_1
 * ]| The tracked ball alone (its silhouette as alpha) over colour bars.
 * |[
 * gst-launch-1.0 -m compositor name=c sink_1::xpos=160 ! video/x-raw,width=320,height=240 !
 * videoconvert ! projtrack start-boxes="<<50,90,60,60>,<210,90,60,60>>" ! fakesink videotestsrc
 * pattern=ball num-buffers=30 ! video/x-raw,width=160,height=240 ! c.sink_0 videotestsrc
 * pattern=ball num-buffers=30 ! video/x-raw,width=160,height=240 ! c.sink_1
 * ]| Two balls at once: a message per ball and frame, with `id=1` and `id=2`.
 */

// The element's class: its type, its pads and metadata, its signals, and the virtual methods, each
// a call into the file that does the job (properties, seeds, stream, events).
#include "gstprojtrack.h"

#include "element.hpp"
#include "events.hpp"
#include "meta.hpp"
#include "objects.hpp"
#include "properties.hpp"
#include "seeds.hpp"
#include "stream.hpp"

GST_DEBUG_CATEGORY(gst_projtrack_debug);

using projtrack::gst::SeedCommand;

enum {
  SIGNAL_TRACK_POINT,
  SIGNAL_TRACK_BOX,
  SIGNAL_RESET,
  SIGNAL_ADD_BOX,
  SIGNAL_ADD_POINT,
  SIGNAL_REMOVE_OBJECT,
  N_SIGNALS
};

static guint signals[N_SIGNALS];

#define VIDEO_FORMATS                                                                             \
  "{ I420, YV12, NV12, NV21, Y42B, Y444, YUY2, UYVY, GRAY8, BGRx, RGBx, xRGB, xBGR, BGRA, RGBA, " \
  "ARGB, ABGR, BGR, RGB, AYUV, A420 }"

static GstStaticPadTemplate sink_template = GST_STATIC_PAD_TEMPLATE(
    "sink", GST_PAD_SINK, GST_PAD_ALWAYS, GST_STATIC_CAPS(GST_VIDEO_CAPS_MAKE(VIDEO_FORMATS)));
static GstStaticPadTemplate src_template = GST_STATIC_PAD_TEMPLATE(
    "src", GST_PAD_SRC, GST_PAD_ALWAYS, GST_STATIC_CAPS(GST_VIDEO_CAPS_MAKE(VIDEO_FORMATS)));

G_DEFINE_TYPE(GstProjtrack, gst_projtrack, GST_TYPE_VIDEO_FILTER)
GST_ELEMENT_REGISTER_DEFINE(projtrack, "projtrack", GST_RANK_NONE, GST_TYPE_PROJTRACK)

static GstStateChangeReturn gst_projtrack_change_state(GstElement* element,
                                                       GstStateChange transition) {
  projtrack::gst::on_state_change(GST_PROJTRACK(element), transition);
  return GST_ELEMENT_CLASS(gst_projtrack_parent_class)->change_state(element, transition);
}

static gboolean gst_projtrack_sink_event(GstBaseTransform* trans, GstEvent* event) {
  projtrack::gst::on_sink_event(GST_PROJTRACK(trans), event);
  return GST_BASE_TRANSFORM_CLASS(gst_projtrack_parent_class)->sink_event(trans, event);
}

static gboolean gst_projtrack_src_event(GstBaseTransform* trans, GstEvent* event) {
  projtrack::gst::on_src_event(GST_PROJTRACK(trans), event);
  return GST_BASE_TRANSFORM_CLASS(gst_projtrack_parent_class)->src_event(trans, event);
}

// Properties bound to a GstController take their values at this buffer's stream time.
static void gst_projtrack_before_transform(GstBaseTransform* trans, GstBuffer* buffer) {
  const GstClockTime stream_time =
      gst_segment_to_stream_time(&trans->segment, GST_FORMAT_TIME, GST_BUFFER_PTS(buffer));
  if (GST_CLOCK_TIME_IS_VALID(stream_time)) gst_object_sync_values(GST_OBJECT(trans), stream_time);
}

static void gst_projtrack_finalize(GObject* object) {
  auto* self = GST_PROJTRACK(object);
  delete self->state;
  G_OBJECT_CLASS(gst_projtrack_parent_class)->finalize(object);
}

static void gst_projtrack_init(GstProjtrack* self) {
  self->state = new projtrack::gst::State;
  // Metadata needs a writable buffer: never pass buffers through untouched.
  gst_base_transform_set_passthrough(GST_BASE_TRANSFORM(self), FALSE);
  // GAP buffers go on as GAP buffers (transform_ip leaves them alone).
  gst_base_transform_set_gap_aware(GST_BASE_TRANSFORM(self), TRUE);
}

static void gst_projtrack_class_init(GstProjtrackClass* klass) {
  auto* gobject_class = G_OBJECT_CLASS(klass);
  auto* element_class = GST_ELEMENT_CLASS(klass);
  auto* trans_class = GST_BASE_TRANSFORM_CLASS(klass);
  auto* filter_class = GST_VIDEO_FILTER_CLASS(klass);

  GST_DEBUG_CATEGORY_INIT(gst_projtrack_debug, "projtrack", 0,
                          "object projection feature tracking");

  gobject_class->set_property = projtrack::gst::set_property;
  gobject_class->get_property = projtrack::gst::get_property;
  gobject_class->finalize = gst_projtrack_finalize;

  projtrack::gst::install_properties(gobject_class);

  // Action signals: g_signal_emit_by_name(element, "track-point", x, y) and so on.
  const auto action = static_cast<GSignalFlags>(G_SIGNAL_RUN_LAST | G_SIGNAL_ACTION);
  signals[SIGNAL_TRACK_POINT] = g_signal_new_class_handler(
      "track-point", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(projtrack::gst::track_point),
      nullptr, nullptr, nullptr, G_TYPE_NONE, 2, G_TYPE_INT, G_TYPE_INT);
  signals[SIGNAL_TRACK_BOX] = g_signal_new_class_handler(
      "track-box", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(projtrack::gst::track_box), nullptr,
      nullptr, nullptr, G_TYPE_NONE, 4, G_TYPE_INT, G_TYPE_INT, G_TYPE_INT, G_TYPE_INT);
  signals[SIGNAL_RESET] = g_signal_new_class_handler("reset", G_TYPE_FROM_CLASS(klass), action,
                                                     G_CALLBACK(projtrack::gst::reset), nullptr,
                                                     nullptr, nullptr, G_TYPE_NONE, 0);
  // Objects followed at once, each with its id: gint id = 0; g_signal_emit_by_name(element,
  // "add-box", x, y, width, height, &id).
  signals[SIGNAL_ADD_BOX] = g_signal_new_class_handler(
      "add-box", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(projtrack::gst::add_box), nullptr,
      nullptr, nullptr, G_TYPE_INT, 4, G_TYPE_INT, G_TYPE_INT, G_TYPE_INT, G_TYPE_INT);
  signals[SIGNAL_ADD_POINT] = g_signal_new_class_handler(
      "add-point", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(projtrack::gst::add_point), nullptr,
      nullptr, nullptr, G_TYPE_INT, 2, G_TYPE_INT, G_TYPE_INT);
  signals[SIGNAL_REMOVE_OBJECT] = g_signal_new_class_handler(
      "remove-object", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(projtrack::gst::remove_object),
      nullptr, nullptr, nullptr, G_TYPE_BOOLEAN, 1, G_TYPE_INT);

  gst_element_class_set_static_metadata(
      element_class, "Object projection feature tracker", "Filter/Analyzer/Video",
      "Tracks one object from its edges and an inner point: centroid, area, box, outline, 3D "
      "pointer",
      PROJTRACK_CONTACT);
  gst_element_class_add_static_metadata(element_class, GST_ELEMENT_METADATA_DOC_URI,
                                        PROJTRACK_DOC_URI);
  gst_element_class_add_static_pad_template(element_class, &sink_template);
  gst_element_class_add_static_pad_template(element_class, &src_template);

  element_class->change_state = GST_DEBUG_FUNCPTR(gst_projtrack_change_state);
  trans_class->start = GST_DEBUG_FUNCPTR(projtrack::gst::start);
  trans_class->stop = GST_DEBUG_FUNCPTR(projtrack::gst::stop);
  trans_class->sink_event = GST_DEBUG_FUNCPTR(gst_projtrack_sink_event);
  trans_class->src_event = GST_DEBUG_FUNCPTR(gst_projtrack_src_event);
  trans_class->before_transform = GST_DEBUG_FUNCPTR(gst_projtrack_before_transform);
  filter_class->set_info = GST_DEBUG_FUNCPTR(projtrack::gst::set_info);
  trans_class->transform_ip = GST_DEBUG_FUNCPTR(projtrack::gst::transform_ip);

  projtrack::gst::projtrack_meta_info();  // GstProjtrackMeta, before any buffer carries one
}
