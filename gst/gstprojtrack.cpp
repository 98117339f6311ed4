/**
 * SECTION:element-projtrack
 * @title: projtrack
 *
 * Tracks one object in video from its edges and one point inside it (the *inner point*), with the
 * estimators of Quesada & León, "Filling-Based Techniques Applied to Object Projection Feature
 * Estimation", or with ours beyond the paper, gap-tolerant filling (the default method): on every
 * buffer it reports the object's centroid, area (px²) and bounding box.
 *
 * With `object-model=appearance` (the default) it finds the whole object's silhouette on every
 * frame — from the object's colours against its surroundings' (chroma is read from the frame's
 * own planes), its edges and its last silhouette — so that a real held object is tracked through
 * its prints and highlights, without the hand that holds it, and the estimator runs on that
 * silhouette's outline. `object-model=edges` is the paper's tracker alone: the estimator on the
 * edge image from the inner point.
 *
 * While tracking, every buffer carries a #GstVideoRegionOfInterestMeta of type `object` (the
 * bounding box) with a `projtrack` parameter structure holding the features, and the element
 * posts an element message named `projtrack` (see docs/element.md for every field). Without an
 * object the message's `status` says why (e.g. `no-inner-point`) and no meta is attached.
 *
 * Without an inner point (`acquisition=auto`, the default) it finds the moving object itself, and
 * finds it again after losing it: an estimate whose area leaks or collapses is refused and
 * reported as `status=lost` with the last good features. Every tracked frame carries a 3D
 * pointer: `position-x`, `position-y` in [-1, 1] and a relative `depth` (smoothed by a One Euro
 * filter), and a quick push toward the camera posts `gesture=push`.
 *
 * An inner point or a box can also be given: the `inner-point-x`/`inner-point-y` and
 * `start-box` properties, the `track-point`, `track-box` and `reset` action signals (one call, no
 * race), or a click: a left mouse-button press arriving from downstream (a click in the window of
 * `autovideosink`) starts tracking at the clicked pixel; a right click stops it.
 * `current-inner-point-x`/`-y` say where the tracker is. `updates` chooses which frames post a
 * message (every frame, on a change, none); conflicting settings are posted as an element warning
 * and `status=invalid-parameters` on the first frame. With `draw=true` the element draws the
 * status and why, x, y and depth, the object's outline and what the estimator did.
 *
 * No frame can stall the pipeline: each has a budget of work (`max-work`, in passes over its
 * pixels, counted in work and never in time) that edge detection and every estimate spend from; a
 * frame that runs out ends with `status=over-budget` and counts as a refused one. A state change
 * to READY or NULL, or a flush, stops a frame in progress (`status=interrupted`), so
 * gst_element_set_state() never waits for a long frame.
 *
 * YUV formats (GRAY8, I420, YV12, NV12, NV21, Y42B, Y444) are read in place, luma and chroma;
 * YUY2 and UYVY have their chroma read in place and their luma gathered once; packed RGB is
 * converted internally. The element works in place; without `draw` it maps frames
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
 * ]| Wave an evenly coloured object: it is found, tracked and, when lost, found again; clicking
 * on an object tracks that one. The overlay says what is tracked, or why not; a message is
 * posted only when that changes.
 * |[
 * gst-launch-1.0 filesrc location=clip.mp4 ! decodebin ! videoconvert ! projtrack
 * method=pixel-filling draw=true inner-point-x=320 inner-point-y=240 ! videoconvert ! autovideosink
 * ]| Tracks from a given inner point in a file, with pixel-filling.
 */

#include "gstprojtrack.h"

#include <gst/video/navigation.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "frame_color.hpp"
#include "frame_mapping.hpp"
#include "overlay.hpp"
#include "projtrack/edge_detection.hpp"
#include "projtrack/sample_clock.hpp"
#include "projtrack/tracker.hpp"

GST_DEBUG_CATEGORY_STATIC(gst_projtrack_debug);
#define GST_CAT_DEFAULT gst_projtrack_debug

using projtrack::Acquisition;
using projtrack::EdgeDetector;
using projtrack::Features;
using projtrack::Method;
using projtrack::ObjectModelKind;
using projtrack::TrackResult;
using projtrack::TrackStatus;

namespace {

constexpr Method kDefaultMethod = Method::GapTolerantFilling;
constexpr EdgeDetector kDefaultEdgeDetector = EdgeDetector::Canny;
constexpr double kMaxGradientThreshold = 10000.0;

// Which frames post a projtrack message (as facedetect's `updates`).
enum class Updates {
  EveryFrame,  // every frame
  OnChange,    // when the status changes, an object is acquired, or a push completes
  None,        // never
};

// Everything a user can set; read by the streaming thread as one copy per frame.
struct Settings {
  Method method = kDefaultMethod;
  projtrack::Params params;
  projtrack::EdgeParams edges;
  projtrack::TrackerParams tracker;
  bool draw = false;
  bool post_messages = true;
  Updates updates = Updates::EveryFrame;
  int seed_x = -1, seed_y = -1;  // the last inner point given (property, signal, click); -1 = none
  projtrack::Rect seed_box;      // the last box given (start-box, track-box); empty = none
};

// What the streaming thread must do to the track before the next frame.
enum class SeedCommand { None, Seed, SeedBox, Reset };

// Per-stream state: created in set_info, dropped in stop; touched by the streaming thread only.
struct Stream {
  projtrack::Tracker tracker;
  projtrack::Trace trace;
  std::vector<std::uint8_t> converted;  // packed RGB frames converted to luma and chroma
  // Why buffers were not read since the caps: each reason is warned once.
  std::set<std::string> layout_warnings;
  int width = 0, height = 0;
  int black_level = 0;  // of edge-detector=input: 16 in limited-range YUV
  guint64 frames = 0;   // for buffers without timestamps
  TrackStatus last_status = TrackStatus::NoInnerPoint;
  // The status of the last message posted (updates=on-change).
  std::optional<TrackStatus> last_posted;
  std::string last_warning;  // the conflict last reported by an element warning
};

}  // namespace

struct _GstProjtrack {
  GstVideoFilter parent;
  Settings* settings;             // GST_OBJECT_LOCK
  SeedCommand pending;            // GST_OBJECT_LOCK
  int frame_width, frame_height;  // GST_OBJECT_LOCK: the negotiated size, for clicks
  int tracked_x, tracked_y;       // GST_OBJECT_LOCK: the tracker's inner point after the last
                                  // frame (current-inner-point-x/y); -1 = none
  Stream* stream;                 // streaming thread
  // Set when the streaming thread must drop what it is doing (PAUSED → READY, a flush): the
  // tracker polls it at its checkpoints; cleared when streaming starts again.
  std::atomic<bool>* interrupt;
};

enum {
  PROP_0,
  PROP_METHOD,
  PROP_RAYS,
  PROP_RECURSION,
  PROP_BLOCK_SIZE,
  PROP_GRID_SIZE,
  PROP_MAX_GAP,
  PROP_MAX_ITERATIONS,
  PROP_CONVERGENCE,
  PROP_EDGE_DETECTOR,
  PROP_EDGE_THRESHOLD_LOW,
  PROP_EDGE_THRESHOLD_HIGH,
  PROP_BLUR,
  PROP_INNER_POINT_X,
  PROP_INNER_POINT_Y,
  PROP_DRAW,
  PROP_POST_MESSAGES,
  PROP_OBJECT_MODEL,
  PROP_ACQUISITION,
  PROP_LEAK_FACTOR,
  PROP_SMOOTHING,
  PROP_SMOOTHING_MIN_CUTOFF,
  PROP_SMOOTHING_BETA,
  PROP_PUSH_THRESHOLD,
  PROP_MAX_WORK,
  PROP_UPDATES,
  PROP_START_BOX,
  PROP_CURRENT_INNER_POINT_X,
  PROP_CURRENT_INNER_POINT_Y,
  N_PROPERTIES
};

static GParamSpec* properties[N_PROPERTIES];

enum { SIGNAL_TRACK_POINT, SIGNAL_TRACK_BOX, SIGNAL_RESET, N_SIGNALS };

#define VIDEO_FORMATS                                                                             \
  "{ I420, YV12, NV12, NV21, Y42B, Y444, YUY2, UYVY, GRAY8, BGRx, RGBx, xRGB, xBGR, BGRA, RGBA, " \
  "ARGB, ABGR, BGR, RGB }"

static GstStaticPadTemplate sink_template = GST_STATIC_PAD_TEMPLATE(
    "sink", GST_PAD_SINK, GST_PAD_ALWAYS, GST_STATIC_CAPS(GST_VIDEO_CAPS_MAKE(VIDEO_FORMATS)));
static GstStaticPadTemplate src_template = GST_STATIC_PAD_TEMPLATE(
    "src", GST_PAD_SRC, GST_PAD_ALWAYS, GST_STATIC_CAPS(GST_VIDEO_CAPS_MAKE(VIDEO_FORMATS)));

// One value per row of the table of methods (include/projtrack/method_table.def): its nick and description.
GType gst_projtrack_method_get_type(void) {
  static GType type = 0;
  static GEnumValue values[projtrack::kMethodCount + 1];  // and the terminating zeros
  if (g_once_init_enter(&type)) {
    for (const projtrack::MethodInfo& m : projtrack::kMethods)
      values[static_cast<int>(m.method)] = {static_cast<gint>(m.method), m.description, m.nick};
    g_once_init_leave(&type, g_enum_register_static("GstProjtrackMethod", values));
  }
  return type;
}

GType gst_projtrack_edge_detector_get_type(void) {
  static GType type = 0;
  static const GEnumValue values[] = {
      {static_cast<gint>(EdgeDetector::Canny), "Canny (hysteresis thresholds low/high)", "canny"},
      {static_cast<gint>(EdgeDetector::Sobel), "Sobel |Gx|+|Gy| >= low (thick edges)", "sobel"},
      {static_cast<gint>(EdgeDetector::Input),
       "Input: the frame already is an edge map (non-zero luma = edge)", "input"},
      {0, nullptr, nullptr}};
  if (g_once_init_enter(&type)) {
    g_once_init_leave(&type, g_enum_register_static("GstProjtrackEdgeDetector", values));
  }
  return type;
}

GType gst_projtrack_acquisition_get_type(void) {
  static GType type = 0;
  static const GEnumValue values[] = {
      {static_cast<gint>(Acquisition::Manual), "Manual: wait for an inner point or a click",
       "manual"},
      {static_cast<gint>(Acquisition::Center), "Center: track what is at the frame centre",
       "center"},
      {static_cast<gint>(Acquisition::Auto),
       "Auto: the most compact closed region where the frame moves", "auto"},
      {0, nullptr, nullptr}};
  if (g_once_init_enter(&type)) {
    g_once_init_leave(&type, g_enum_register_static("GstProjtrackAcquisition", values));
  }
  return type;
}

GType gst_projtrack_object_model_get_type(void) {
  static GType type = 0;
  static const GEnumValue values[] = {
      {static_cast<gint>(ObjectModelKind::Edges),
       "Edges: the paper's tracker, the estimator on the edge image alone", "edges"},
      {static_cast<gint>(ObjectModelKind::Appearance),
       "Appearance: the whole object's silhouette from its colours, its edges and its motion; "
       "the estimator runs on its outline",
       "appearance"},
      {0, nullptr, nullptr}};
  if (g_once_init_enter(&type)) {
    g_once_init_leave(&type, g_enum_register_static("GstProjtrackObjectModel", values));
  }
  return type;
}

GType gst_projtrack_updates_get_type(void) {
  static GType type = 0;
  static const GEnumValue values[] = {
      {static_cast<gint>(Updates::EveryFrame), "A message for every frame", "every-frame"},
      {static_cast<gint>(Updates::OnChange),
       "A message when the status changes, an object is acquired, or a push completes",
       "on-change"},
      {static_cast<gint>(Updates::None), "No messages (the ROI meta is still attached)", "none"},
      {0, nullptr, nullptr}};
  if (g_once_init_enter(&type)) {
    g_once_init_leave(&type, g_enum_register_static("GstProjtrackUpdates", values));
  }
  return type;
}

static guint signals[N_SIGNALS];

G_DEFINE_TYPE(GstProjtrack, gst_projtrack, GST_TYPE_VIDEO_FILTER)
GST_ELEMENT_REGISTER_DEFINE(projtrack, "projtrack", GST_RANK_NONE, GST_TYPE_PROJTRACK)

// The inner point the user gives (a property, a click), and what the streaming thread does with
// it before its next frame, are written here only: a whole point seeds the track there; a point
// with a coordinate of -1 stops it, unless `awaiting_coordinate` (a property just gave the first
// coordinate of a new point: the track goes on until the second comes).
static void set_inner_point_locked(GstProjtrack* self, int x, int y,
                                   bool awaiting_coordinate = false) {
  Settings& s = *self->settings;
  s.seed_x = x;
  s.seed_y = y;
  s.seed_box = {};
  if (x >= 0 && y >= 0)
    self->pending = SeedCommand::Seed;
  else if (!awaiting_coordinate)
    self->pending = SeedCommand::Reset;
}

// A box to start from (start-box, track-box): the track starts there on the next frame; an empty
// box stops it.
static void set_box_locked(GstProjtrack* self, const projtrack::Rect& box) {
  Settings& s = *self->settings;
  s.seed_x = s.seed_y = -1;
  s.seed_box = box.empty() ? projtrack::Rect{} : box;
  self->pending = box.empty() ? SeedCommand::Reset : SeedCommand::SeedBox;
}

// start-box: x, y, width, height, or nothing (an empty array, or width or height under 1).
static projtrack::Rect box_of(const GValue* array) {
  if (gst_value_array_get_size(array) != 4) return {};
  int v[4];
  for (guint i = 0; i < 4; ++i) {
    const GValue* item = gst_value_array_get_value(array, i);
    if (!G_VALUE_HOLDS_INT(item)) return {};
    v[i] = g_value_get_int(item);
  }
  return {v[0], v[1], v[2], v[3]};
}

static void set_box_value(GValue* array, const projtrack::Rect& box) {
  if (box.empty()) return;
  for (int v : {box.x, box.y, box.width, box.height}) {
    GValue item = G_VALUE_INIT;
    g_value_init(&item, G_TYPE_INT);
    g_value_set_int(&item, v);
    gst_value_array_append_and_take_value(array, &item);
  }
}

static void gst_projtrack_set_property(GObject* object, guint prop_id, const GValue* value,
                                       GParamSpec* pspec) {
  auto* self = GST_PROJTRACK(object);
  GST_OBJECT_LOCK(self);
  Settings& s = *self->settings;
  switch (prop_id) {
    case PROP_METHOD:
      s.method = static_cast<Method>(g_value_get_enum(value));
      break;
    case PROP_RAYS:
      s.params.rays = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_RECURSION:
      s.params.recursion = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_BLOCK_SIZE:
      s.params.block_size = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_GRID_SIZE:
      s.params.grid_size = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_MAX_GAP:
      s.params.max_gap = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_MAX_ITERATIONS:
      s.params.max_iterations = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_CONVERGENCE:
      s.params.convergence = g_value_get_double(value);
      break;
    case PROP_EDGE_DETECTOR:
      s.edges.detector = static_cast<EdgeDetector>(g_value_get_enum(value));
      break;
    case PROP_EDGE_THRESHOLD_LOW:
      s.edges.low = g_value_get_double(value);
      break;
    case PROP_EDGE_THRESHOLD_HIGH:
      s.edges.high = g_value_get_double(value);
      break;
    case PROP_BLUR:
      s.edges.blur = static_cast<int>(g_value_get_uint(value));
      break;
    case PROP_INNER_POINT_X:
    case PROP_INNER_POINT_Y: {
      const int v = g_value_get_int(value);
      const bool x = prop_id == PROP_INNER_POINT_X;
      set_inner_point_locked(self, x ? v : s.seed_x, x ? s.seed_y : v, v >= 0);
      break;
    }
    case PROP_DRAW:
      s.draw = g_value_get_boolean(value);
      break;
    case PROP_POST_MESSAGES:
      s.post_messages = g_value_get_boolean(value);
      break;
    case PROP_OBJECT_MODEL:
      s.tracker.model = static_cast<ObjectModelKind>(g_value_get_enum(value));
      break;
    case PROP_ACQUISITION:
      s.tracker.acquisition = static_cast<Acquisition>(g_value_get_enum(value));
      break;
    case PROP_LEAK_FACTOR:
      s.tracker.leak_factor = g_value_get_double(value);
      break;
    case PROP_SMOOTHING:
      s.tracker.smoothing = g_value_get_boolean(value);
      break;
    case PROP_SMOOTHING_MIN_CUTOFF:
      s.tracker.filter.min_cutoff = g_value_get_double(value);
      break;
    case PROP_SMOOTHING_BETA:
      s.tracker.filter.beta = g_value_get_double(value);
      break;
    case PROP_PUSH_THRESHOLD:
      s.tracker.push.threshold = g_value_get_double(value);
      break;
    case PROP_MAX_WORK:
      s.tracker.max_work = g_value_get_double(value);
      break;
    case PROP_UPDATES:
      s.updates = static_cast<Updates>(g_value_get_enum(value));
      break;
    case PROP_START_BOX:
      set_box_locked(self, box_of(value));
      break;
    default:
      G_OBJECT_WARN_INVALID_PROPERTY_ID(object, prop_id, pspec);
      break;
  }
  GST_OBJECT_UNLOCK(self);
}

static void gst_projtrack_get_property(GObject* object, guint prop_id, GValue* value,
                                       GParamSpec* pspec) {
  auto* self = GST_PROJTRACK(object);
  GST_OBJECT_LOCK(self);
  const Settings& s = *self->settings;
  switch (prop_id) {
    case PROP_METHOD:
      g_value_set_enum(value, static_cast<gint>(s.method));
      break;
    case PROP_RAYS:
      g_value_set_uint(value, s.params.rays);
      break;
    case PROP_RECURSION:
      g_value_set_uint(value, s.params.recursion);
      break;
    case PROP_BLOCK_SIZE:
      g_value_set_uint(value, s.params.block_size);
      break;
    case PROP_GRID_SIZE:
      g_value_set_uint(value, s.params.grid_size);
      break;
    case PROP_MAX_GAP:
      g_value_set_uint(value, s.params.max_gap);
      break;
    case PROP_MAX_ITERATIONS:
      g_value_set_uint(value, s.params.max_iterations);
      break;
    case PROP_CONVERGENCE:
      g_value_set_double(value, s.params.convergence);
      break;
    case PROP_EDGE_DETECTOR:
      g_value_set_enum(value, static_cast<gint>(s.edges.detector));
      break;
    case PROP_EDGE_THRESHOLD_LOW:
      g_value_set_double(value, s.edges.low);
      break;
    case PROP_EDGE_THRESHOLD_HIGH:
      g_value_set_double(value, s.edges.high);
      break;
    case PROP_BLUR:
      g_value_set_uint(value, s.edges.blur);
      break;
    case PROP_INNER_POINT_X:
      g_value_set_int(value, s.seed_x);
      break;
    case PROP_INNER_POINT_Y:
      g_value_set_int(value, s.seed_y);
      break;
    case PROP_DRAW:
      g_value_set_boolean(value, s.draw);
      break;
    case PROP_POST_MESSAGES:
      g_value_set_boolean(value, s.post_messages);
      break;
    case PROP_OBJECT_MODEL:
      g_value_set_enum(value, static_cast<gint>(s.tracker.model));
      break;
    case PROP_ACQUISITION:
      g_value_set_enum(value, static_cast<gint>(s.tracker.acquisition));
      break;
    case PROP_LEAK_FACTOR:
      g_value_set_double(value, s.tracker.leak_factor);
      break;
    case PROP_SMOOTHING:
      g_value_set_boolean(value, s.tracker.smoothing);
      break;
    case PROP_SMOOTHING_MIN_CUTOFF:
      g_value_set_double(value, s.tracker.filter.min_cutoff);
      break;
    case PROP_SMOOTHING_BETA:
      g_value_set_double(value, s.tracker.filter.beta);
      break;
    case PROP_PUSH_THRESHOLD:
      g_value_set_double(value, s.tracker.push.threshold);
      break;
    case PROP_MAX_WORK:
      g_value_set_double(value, s.tracker.max_work);
      break;
    case PROP_UPDATES:
      g_value_set_enum(value, static_cast<gint>(s.updates));
      break;
    case PROP_START_BOX:
      set_box_value(value, s.seed_box);
      break;
    case PROP_CURRENT_INNER_POINT_X:
      g_value_set_int(value, self->tracked_x);
      break;
    case PROP_CURRENT_INNER_POINT_Y:
      g_value_set_int(value, self->tracked_y);
      break;
    default:
      G_OBJECT_WARN_INVALID_PROPERTY_ID(object, prop_id, pspec);
      break;
  }
  GST_OBJECT_UNLOCK(self);
}

// A restart (caps change, stop/start) begins again from the last inner point given, if any.
static void reseed_locked(GstProjtrack* self) {
  if (!self->settings->seed_box.empty())
    set_box_locked(self, self->settings->seed_box);
  else
    set_inner_point_locked(self, self->settings->seed_x, self->settings->seed_y);
}

static void notify_inner_point(GstProjtrack* self) {
  for (int prop : {PROP_INNER_POINT_X, PROP_INNER_POINT_Y, PROP_START_BOX})
    g_object_notify_by_pspec(G_OBJECT(self), properties[prop]);
}

// Action signals: an app starts or stops a track in one call (no race between two properties).
static void gst_projtrack_track_point(GstProjtrack* self, gint x, gint y) {
  GST_OBJECT_LOCK(self);
  set_inner_point_locked(self, x, y);  // a negative coordinate stops the track
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "track-point %d, %d", x, y);
  notify_inner_point(self);
}

static void gst_projtrack_track_box(GstProjtrack* self, gint x, gint y, gint width, gint height) {
  GST_OBJECT_LOCK(self);
  set_box_locked(self, {x, y, width, height});  // an empty box stops the track
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "track-box %d, %d, %dx%d", x, y, width, height);
  notify_inner_point(self);
}

static void gst_projtrack_reset(GstProjtrack* self) {
  GST_OBJECT_LOCK(self);
  set_inner_point_locked(self, -1, -1);
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "reset");
  notify_inner_point(self);
}

static gboolean gst_projtrack_set_info(GstVideoFilter* filter, GstCaps*, GstVideoInfo* in_info,
                                       GstCaps*, GstVideoInfo*) {
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

// Streaming starts (READY → PAUSED): a stop asked before is over.
static gboolean gst_projtrack_start(GstBaseTransform* trans) {
  GST_PROJTRACK(trans)->interrupt->store(false);
  return TRUE;
}

// PAUSED → READY waits for the streaming thread to leave the element (the pads are deactivated
// under its stream lock): the flag makes a frame in progress stop at the tracker's next
// checkpoint instead of running to its end. That frame passes through with status=interrupted.
static GstStateChangeReturn gst_projtrack_change_state(GstElement* element,
                                                       GstStateChange transition) {
  auto* self = GST_PROJTRACK(element);
  if (transition == GST_STATE_CHANGE_PAUSED_TO_READY) {
    GST_DEBUG_OBJECT(self, "stopping: a frame in progress is interrupted");
    self->interrupt->store(true);
  }
  return GST_ELEMENT_CLASS(gst_projtrack_parent_class)->change_state(element, transition);
}

// A flush (a seek) likewise stops a frame in progress; the flush's end lets the next frames run.
static gboolean gst_projtrack_sink_event(GstBaseTransform* trans, GstEvent* event) {
  auto* self = GST_PROJTRACK(trans);
  if (GST_EVENT_TYPE(event) == GST_EVENT_FLUSH_START) {
    GST_DEBUG_OBJECT(self, "flushing: a frame in progress is interrupted");
    self->interrupt->store(true);
  } else if (GST_EVENT_TYPE(event) == GST_EVENT_FLUSH_STOP) {
    self->interrupt->store(false);
  }
  return GST_BASE_TRANSFORM_CLASS(gst_projtrack_parent_class)->sink_event(trans, event);
}

static gboolean gst_projtrack_stop(GstBaseTransform* trans) {
  auto* self = GST_PROJTRACK(trans);
  delete self->stream;
  self->stream = nullptr;
  GST_OBJECT_LOCK(self);
  reseed_locked(self);
  self->tracked_x = self->tracked_y = -1;
  GST_OBJECT_UNLOCK(self);
  return TRUE;
}

// Left click in the picture: track from the clicked pixel. Right click: stop tracking. Clicks
// outside the picture (a letterboxed window's borders) are ignored.
static gboolean gst_projtrack_src_event(GstBaseTransform* trans, GstEvent* event) {
  auto* self = GST_PROJTRACK(trans);
  if (GST_EVENT_TYPE(event) == GST_EVENT_NAVIGATION &&
      gst_navigation_event_get_type(event) == GST_NAVIGATION_EVENT_MOUSE_BUTTON_PRESS) {
    gint button = 0;
    gdouble x = 0, y = 0;
    if (gst_navigation_event_parse_mouse_button_event(event, &button, &x, &y) &&
        (button == 1 || button == 3) && std::isfinite(x) && std::isfinite(y)) {
      GST_OBJECT_LOCK(self);
      const double px = std::round(x), py = std::round(y);
      const bool in_picture =
          px >= 0 && py >= 0 && px < self->frame_width && py < self->frame_height;
      const bool changed = button == 3 || in_picture;
      if (button == 3)
        set_inner_point_locked(self, -1, -1);
      else if (in_picture)
        set_inner_point_locked(self, static_cast<int>(px), static_cast<int>(py));
      const int sx = self->settings->seed_x, sy = self->settings->seed_y;
      GST_OBJECT_UNLOCK(self);
      GST_INFO_OBJECT(self, "click (button %d) at %.1f, %.1f: %s inner point %d, %d", button, x, y,
                      changed ? "new" : "outside the picture, kept the", sx, sy);
      if (changed) notify_inner_point(self);
    }
  }
  return GST_BASE_TRANSFORM_CLASS(gst_projtrack_parent_class)->src_event(trans, event);
}

// The features, the pose and the status: the ROI meta's parameters and the message's core.
static GstStructure* result_structure(const TrackResult& r, Method method) {
  GstStructure* s = gst_structure_new(
      "projtrack", "status", G_TYPE_STRING, projtrack::status_name(r.status).data(), "method",
      G_TYPE_STRING, projtrack::method_name(method).data(), nullptr);
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
  if (r.push) gst_structure_set(s, "gesture", G_TYPE_STRING, "push", nullptr);
  return s;
}

static void attach_meta(GstBuffer* buffer, const TrackResult& r, Method method) {
  const projtrack::Rect& b = r.features.bbox;
  GstVideoRegionOfInterestMeta* meta =
      gst_buffer_add_video_region_of_interest_meta(buffer, "object", b.x, b.y, b.width, b.height);
  gst_video_region_of_interest_meta_add_param(meta, result_structure(r, method));
}

static GstMessage* result_message(GstProjtrack* self, GstBuffer* buffer, const TrackResult& r,
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
  } else if (const std::optional<projtrack::Point2i>& inner = r.inner_point) {
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

// Runs edges + estimator on one mapped frame, and draws when asked.
static TrackResult process(GstProjtrack* self, GstVideoFrame* frame, const Settings& s,
                           SeedCommand command) {
  Stream& st = *self->stream;
  if (command == SeedCommand::Seed)
    st.tracker.seed({s.seed_x, s.seed_y});
  else if (command == SeedCommand::SeedBox)
    st.tracker.seed_box(s.seed_box);
  else if (command == SeedCommand::Reset)
    st.tracker.reset();
  projtrack::EdgeParams edge_params = s.edges;
  edge_params.input_black_level = st.black_level;
  const projtrack::ColorView color = projtrack::gst::frame_color(frame, st.converted);
  projtrack::Trace* trace = s.draw ? &st.trace : nullptr;
  // Seconds for the smoothing and the push detector: the buffer's time, else the assumed rate.
  const GstClockTime pts = GST_BUFFER_PTS(frame->buffer);
  const double t = GST_CLOCK_TIME_IS_VALID(pts)
                       ? static_cast<double>(pts) / GST_SECOND
                       : static_cast<double>(st.frames) / projtrack::kAssumedFrameRate;
  ++st.frames;
  // The tracker computes the edges itself: while tracking, only around the object.
  TrackResult r = st.tracker.track(color, edge_params, t, s.method, s.params, s.tracker, trace);
  if (s.draw) {
    projtrack::gst::draw_overlay(frame, s.method, r, st.trace);
    if (st.trace.rays_not_recorded)
      GST_LOG_OBJECT(self, "overlay: %zu rays not recorded", st.trace.rays_not_recorded);
  }
  return r;
}

// Whether this frame posts a message: every frame; on a change (another status, an acquisition,
// a push); or never.
static bool worth_posting(Updates updates, const TrackResult& r, std::optional<TrackStatus>& last) {
  const bool changed = last != r.status || r.acquired || r.push;
  last = r.status;
  return updates == Updates::EveryFrame || (updates == Updates::OnChange && changed);
}

// A buffer whose layout does not fit its memory is not read: it passes through untouched, the
// track waits (a seed given meanwhile applies to the next readable frame), and the status says
// why. One element warning per reason and caps; the debug log has every frame.
static TrackResult unread_frame(GstProjtrack* self, const projtrack::gst::FrameMapping& mapping,
                                SeedCommand command) {
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

// In place, as GstVideoFilter would, but the frame is mapped for writing only when the overlay
// draws: a read-only map never copies a buffer that another branch (a tee) shares.
static GstFlowReturn gst_projtrack_transform_ip(GstBaseTransform* trans, GstBuffer* buffer) {
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
  const projtrack::gst::FrameMapping mapping = projtrack::gst::map_frame_checked(
      &frame, &filter->in_info, buffer, s.draw ? GST_MAP_READWRITE : GST_MAP_READ);
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
  if (projtrack::has_features(r.status)) attach_meta(buffer, r, s.method);

  Stream& st = *self->stream;
  const std::string& detail = r.detail.empty() ? r.features.detail : r.detail;
  if (r.status != st.last_status) {
    GST_INFO_OBJECT(self, "status %s -> %s%s%s", projtrack::status_name(st.last_status).data(),
                    projtrack::status_name(r.status).data(), detail.empty() ? "" : ": ",
                    detail.c_str());
    st.last_status = r.status;
  }
  // Settings that conflict are said at once, whatever `updates` is, and again when they change.
  if (r.status != TrackStatus::InvalidParameters) {
    st.last_warning.clear();
  } else if (detail != st.last_warning) {
    st.last_warning = detail;
    GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS, ("Conflicting settings: %s", detail.c_str()),
                        ("nothing is tracked until they are fixed"));
  }
  if (r.push) GST_INFO_OBJECT(self, "gesture: push");
  const std::optional<projtrack::Point2i>& inner = r.inner_point;
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

static void gst_projtrack_finalize(GObject* object) {
  auto* self = GST_PROJTRACK(object);
  delete self->stream;
  delete self->settings;
  delete self->interrupt;
  G_OBJECT_CLASS(gst_projtrack_parent_class)->finalize(object);
}

static void gst_projtrack_init(GstProjtrack* self) {
  self->settings = new Settings;
  self->pending = SeedCommand::None;
  self->frame_width = self->frame_height = 0;
  self->tracked_x = self->tracked_y = -1;
  self->stream = nullptr;
  self->interrupt = new std::atomic<bool>(false);
  // Metadata needs a writable buffer: never pass buffers through untouched.
  gst_base_transform_set_passthrough(GST_BASE_TRANSFORM(self), FALSE);
}

// A property's blurb: `what` it does, after the methods it tunes (those of the table of methods
// for which `tunes` holds), as "grid-filling and gap-tolerant-filling: what". The list comes from
// the table's traits, so that a new method keeps the blurbs true. Interned: the blurb lives as long
// as the process, as G_PARAM_STATIC_STRINGS wants.
template <class Tunes>
static const char* blurb_of_methods(Tunes tunes, const char* what) {
  std::vector<const char*> nicks;
  for (const projtrack::MethodInfo& m : projtrack::kMethods)
    if (tunes(m)) nicks.push_back(m.nick);
  std::string blurb;
  for (std::size_t i = 0; i < nicks.size(); ++i)
    blurb += std::string(i == 0 ? "" : i + 1 == nicks.size() ? " and " : ", ") + nicks[i];
  return g_intern_string((blurb + ": " + what).c_str());
}

// The methods that read the parameter of `bit` (the table's `reads` column).
static auto reading(projtrack::ReadsParam bit) {
  return [bit](const projtrack::MethodInfo& m) { return (m.reads & bit) != 0; };
}

static bool iterates(const projtrack::MethodInfo& m) { return m.iterative; }

static void gst_projtrack_class_init(GstProjtrackClass* klass) {
  auto* gobject_class = G_OBJECT_CLASS(klass);
  auto* element_class = GST_ELEMENT_CLASS(klass);
  auto* trans_class = GST_BASE_TRANSFORM_CLASS(klass);
  auto* filter_class = GST_VIDEO_FILTER_CLASS(klass);

  GST_DEBUG_CATEGORY_INIT(gst_projtrack_debug, "projtrack", 0,
                          "object projection feature tracking");

  gobject_class->set_property = gst_projtrack_set_property;
  gobject_class->get_property = gst_projtrack_get_property;
  gobject_class->finalize = gst_projtrack_finalize;

  const auto flags = static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS |
                                              GST_PARAM_MUTABLE_PLAYING);
  const projtrack::Params p;
  const projtrack::EdgeParams e;
  // Blurbs say what a setting does in a user's words and which methods it matters to (every
  // method keeps the inner point centred with `rays` rays).
  properties[PROP_METHOD] = g_param_spec_enum(
      "method", "Method",
      g_intern_string((std::string("How the object's centroid and area are measured inside its "
                                   "outline: rays cast from the inner point, or a fill (") +
                       projtrack::method_info(kDefaultMethod).nick +
                       ", the default, does not leak through small breaks in the outline)")
                          .c_str()),
      GST_TYPE_PROJTRACK_METHOD, static_cast<gint>(kDefaultMethod), flags);
  properties[PROP_RAYS] = g_param_spec_uint(
      "rays", "Rays",
      "How many rays are cast from the inner point: the measurement of the ray-casting methods, "
      "and, for every method, how the inner point is kept in the middle of the object",
      projtrack::kMinRays, projtrack::kMaxRays, p.rays, flags);
  properties[PROP_RECURSION] = g_param_spec_uint(
      "recursion", "Recursion",
      blurb_of_methods(reading(projtrack::kReadsRecursion),
                       "how many times rays are cast again from where they hit (rays to the power "
                       "recursion must stay at most 1048576)"),
      projtrack::kMinRecursion, projtrack::kMaxRecursion, p.recursion, flags);
  properties[PROP_BLOCK_SIZE] = g_param_spec_uint(
      "block-size", "Block size",
      blurb_of_methods(reading(projtrack::kReadsBlockSize),
                       "side, in pixels, of the squares that the rays mark as the object"),
      1, projtrack::kMaxCellSize, p.block_size, flags);
  properties[PROP_GRID_SIZE] = g_param_spec_uint(
      "grid-size", "Grid size",
      blurb_of_methods(reading(projtrack::kReadsGridSize),
                       "spacing, in pixels, of the grid lines the fill follows (smaller: more "
                       "exact, slower)"),
      1, projtrack::kMaxCellSize, p.grid_size, flags);
  properties[PROP_MAX_GAP] = g_param_spec_uint(
      "max-gap", "Max gap",
      blurb_of_methods(reading(projtrack::kReadsMaxGap),
                       "the longest break in the object's outline, in pixels, that the fill will "
                       "not leak through"),
      1, projtrack::kMaxGap, p.max_gap, flags);
  properties[PROP_MAX_ITERATIONS] = g_param_spec_uint(
      "max-iterations", "Max iterations",
      blurb_of_methods(iterates, "at most this many cast-and-move rounds per frame"), 1,
      projtrack::kMaxIterations, p.max_iterations, flags);
  properties[PROP_CONVERGENCE] = g_param_spec_double(
      "convergence", "Convergence",
      blurb_of_methods(iterates,
                       "stop the rounds when the inner point and the centroid move less than this "
                       "many pixels"),
      0.0, projtrack::kMaxConvergence, p.convergence, flags);
  properties[PROP_EDGE_DETECTOR] = g_param_spec_enum(
      "edge-detector", "Edge detector",
      "How the object's outline is found in the picture (every method): Canny, Sobel, or the "
      "input already is an edge image",
      GST_TYPE_PROJTRACK_EDGE_DETECTOR, static_cast<gint>(kDefaultEdgeDetector), flags);
  properties[PROP_EDGE_THRESHOLD_LOW] = g_param_spec_double(
      "edge-threshold-low", "Edge threshold low",
      "Every method: the weakest contrast that can continue an edge (Canny), or that makes an "
      "edge (Sobel). A step of C grey levels scores 4*C. Must not exceed edge-threshold-high",
      0.0, kMaxGradientThreshold, e.low, flags);
  properties[PROP_EDGE_THRESHOLD_HIGH] = g_param_spec_double(
      "edge-threshold-high", "Edge threshold high",
      "Every method with the Canny detector: the contrast that starts an edge (a step of C grey "
      "levels scores 4*C)",
      0.0, kMaxGradientThreshold, e.high, flags);
  properties[PROP_BLUR] = g_param_spec_uint(
      "blur", "Blur",
      "Every method: how many times the picture is softened (3x3 box blur) before its edges are "
      "found; more ignores more noise and texture",
      0, projtrack::kMaxBlurPasses, e.blur, flags);
  properties[PROP_INNER_POINT_X] = g_param_spec_int(
      "inner-point-x", "Inner point x",
      "Column of a pixel inside the object to track, with inner-point-y (every method): setting "
      "it starts the track there, -1 stops it. Clicks update it. From an app, the track-point "
      "signal sets both at once",
      -1, G_MAXINT, -1, flags);
  properties[PROP_INNER_POINT_Y] = g_param_spec_int(
      "inner-point-y", "Inner point y",
      "Row of a pixel inside the object to track, with inner-point-x (every method): setting it "
      "starts the track there, -1 stops it. Clicks update it",
      -1, G_MAXINT, -1, flags);
  properties[PROP_START_BOX] = gst_param_spec_array(
      "start-box", "Start box",
      "A box around the object to track: <x, y, width, height> in pixels, e.g. "
      "start-box=\"<280,200,80,80>\" (every method; the appearance model learns the object "
      "from it). Setting it starts the track there; <> stops it. Apps: the track-box signal",
      g_param_spec_int("coordinate", "Coordinate", "x, y, width or height", G_MININT, G_MAXINT, 0,
                       static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS)),
      flags);
  properties[PROP_CURRENT_INNER_POINT_X] = g_param_spec_int(
      "current-inner-point-x", "Current inner point x",
      "Column where the tracker's inner point is now, after the last frame (-1: not tracking)", -1,
      G_MAXINT, -1, static_cast<GParamFlags>(G_PARAM_READABLE | G_PARAM_STATIC_STRINGS));
  properties[PROP_CURRENT_INNER_POINT_Y] = g_param_spec_int(
      "current-inner-point-y", "Current inner point y",
      "Row where the tracker's inner point is now, after the last frame (-1: not tracking)", -1,
      G_MAXINT, -1, static_cast<GParamFlags>(G_PARAM_READABLE | G_PARAM_STATIC_STRINGS));
  properties[PROP_DRAW] = g_param_spec_boolean(
      "draw", "Draw",
      "Draw on the video what is tracked: the status and why, x, y and depth, the object's "
      "outline and box, and what the method did (rays, blocks, filled pixels or grid lines)",
      FALSE, flags);
  properties[PROP_POST_MESSAGES] = g_param_spec_boolean(
      "post-messages", "Post messages",
      "Post projtrack element messages on the bus (how often: updates); false posts none", TRUE,
      flags);
  properties[PROP_UPDATES] = g_param_spec_enum(
      "updates", "Updates",
      "Which frames post a projtrack message: every frame, only when something changes (the "
      "status, an object acquired, a push), or none",
      GST_TYPE_PROJTRACK_UPDATES, static_cast<gint>(Updates::EveryFrame), flags);
  const projtrack::TrackerParams tp;
  properties[PROP_OBJECT_MODEL] = g_param_spec_enum(
      "object-model", "Object model",
      "What the tracker knows of the object, for every method: its edges alone (the paper's "
      "tracker), or its appearance (its colours against its surroundings, its edges and its "
      "motion: for real footage)",
      GST_TYPE_PROJTRACK_OBJECT_MODEL, static_cast<gint>(tp.model), flags);
  properties[PROP_ACQUISITION] = g_param_spec_enum(
      "acquisition", "Acquisition",
      "How tracking starts, and starts again after a loss, when no inner point or box is given: "
      "wait, the frame centre, or the object that moves (every method)",
      GST_TYPE_PROJTRACK_ACQUISITION, static_cast<gint>(tp.acquisition), flags);
  properties[PROP_LEAK_FACTOR] = g_param_spec_double(
      "leak-factor", "Leak factor",
      "Every method: an object whose area grows or shrinks by more than this factor from one "
      "frame to the next is refused (status lost): the fill leaked, or the inner point slipped "
      "into a small region",
      1.05, 1000.0, tp.leak_factor, flags);
  properties[PROP_SMOOTHING] = g_param_spec_boolean(
      "smoothing", "Smoothing", "Smooth position-x, position-y and depth (a One Euro filter)",
      tp.smoothing, flags);
  properties[PROP_SMOOTHING_MIN_CUTOFF] = g_param_spec_double(
      "smoothing-min-cutoff", "Smoothing minimum cutoff",
      "How smooth the pointer is at rest, in Hz: lower is smoother but lags more", 0.01, 100.0,
      tp.filter.min_cutoff, flags);
  properties[PROP_SMOOTHING_BETA] = g_param_spec_double(
      "smoothing-beta", "Smoothing beta",
      "How quickly smoothing gives way when the object moves fast: higher lags less", 0.0, 1000.0,
      tp.filter.beta, flags);
  properties[PROP_PUSH_THRESHOLD] = g_param_spec_double(
      "push-threshold", "Push threshold",
      "A push (a click) is the object brought quickly toward the camera by more than this "
      "fraction of its depth, and back",
      0.01, 10.0, tp.push.threshold, flags);
  properties[PROP_MAX_WORK] = g_param_spec_double(
      "max-work", "Max work",
      "Every method: how much work one frame may take, in passes over the frame's pixels (a "
      "fill that covers the whole frame costs about 1 to 4). A frame that needs more is cut "
      "short and reported with status over-budget; settings that can never fit (millions of "
      "rays) are refused. It bounds the time a frame takes whatever the video shows; 0: no "
      "limit",
      0.0, projtrack::kMaxMaxWork, tp.max_work, flags);
  g_object_class_install_properties(gobject_class, N_PROPERTIES, properties);

  // Action signals: g_signal_emit_by_name(element, "track-point", x, y) and so on.
  const auto action = static_cast<GSignalFlags>(G_SIGNAL_RUN_LAST | G_SIGNAL_ACTION);
  signals[SIGNAL_TRACK_POINT] = g_signal_new_class_handler(
      "track-point", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(gst_projtrack_track_point),
      nullptr, nullptr, nullptr, G_TYPE_NONE, 2, G_TYPE_INT, G_TYPE_INT);
  signals[SIGNAL_TRACK_BOX] = g_signal_new_class_handler(
      "track-box", G_TYPE_FROM_CLASS(klass), action, G_CALLBACK(gst_projtrack_track_box), nullptr,
      nullptr, nullptr, G_TYPE_NONE, 4, G_TYPE_INT, G_TYPE_INT, G_TYPE_INT, G_TYPE_INT);
  signals[SIGNAL_RESET] = g_signal_new_class_handler("reset", G_TYPE_FROM_CLASS(klass), action,
                                                     G_CALLBACK(gst_projtrack_reset), nullptr,
                                                     nullptr, nullptr, G_TYPE_NONE, 0);

  gst_element_class_set_static_metadata(
      element_class, "Object projection feature tracker", "Filter/Analyzer/Video",
      "Tracks one object (found by its motion, a click, an inner point or a box) and reports its "
      "centroid, area, bounding box and a 3D pointer (x, y, depth, push clicks) on every frame: "
      "a GstVideoRegionOfInterestMeta of type \"object\" with a \"projtrack\" parameter "
      "structure on each buffer, and a \"projtrack\" element message on the bus",
      PROJTRACK_CONTACT);
  gst_element_class_add_static_pad_template(element_class, &sink_template);
  gst_element_class_add_static_pad_template(element_class, &src_template);

  element_class->change_state = GST_DEBUG_FUNCPTR(gst_projtrack_change_state);
  trans_class->start = GST_DEBUG_FUNCPTR(gst_projtrack_start);
  trans_class->stop = GST_DEBUG_FUNCPTR(gst_projtrack_stop);
  trans_class->sink_event = GST_DEBUG_FUNCPTR(gst_projtrack_sink_event);
  trans_class->src_event = GST_DEBUG_FUNCPTR(gst_projtrack_src_event);
  filter_class->set_info = GST_DEBUG_FUNCPTR(gst_projtrack_set_info);
  trans_class->transform_ip = GST_DEBUG_FUNCPTR(gst_projtrack_transform_ip);

  gst_type_mark_as_plugin_api(GST_TYPE_PROJTRACK_METHOD, static_cast<GstPluginAPIFlags>(0));
  gst_type_mark_as_plugin_api(GST_TYPE_PROJTRACK_ACQUISITION, static_cast<GstPluginAPIFlags>(0));
  gst_type_mark_as_plugin_api(GST_TYPE_PROJTRACK_OBJECT_MODEL, static_cast<GstPluginAPIFlags>(0));
  gst_type_mark_as_plugin_api(GST_TYPE_PROJTRACK_EDGE_DETECTOR, static_cast<GstPluginAPIFlags>(0));
  gst_type_mark_as_plugin_api(GST_TYPE_PROJTRACK_UPDATES, static_cast<GstPluginAPIFlags>(0));
}
