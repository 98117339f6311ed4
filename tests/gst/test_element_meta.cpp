// GstProjtrackMeta through the elements an application puts after projtrack (videoconvert,
// videoscale, tee, queue, a buffer copy; videoflip and videocrop, which drop it in GStreamer
// 1.22), read with the public header gstprojtrackmeta.h; and what identifies a track: the
// track-id (new on every acquisition), the element's name, the ROI meta's id, the outline.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "gstprojtrackmeta.h"
#include "harness.hpp"

namespace {

const auto* const kGst = ::testing::AddGlobalTestEnvironment(new projtrack::test::GstInit);

// The metas a pipeline's buffers carried: at projtrack's src pad, by PTS, and at the sink.
struct Seen {
  std::map<GstClockTime, GstStructure*> source;
  struct AtSink {
    GstClockTime pts;
    int width, height;
    GstStructure* meta;  // null: none
    std::vector<GstVideoRegionOfInterestMeta> rois;
  };
  std::vector<AtSink> sink;
  ~Seen() {
    for (auto& [pts, s] : source) gst_structure_free(s);
    for (AtSink& a : sink)
      if (a.meta) gst_structure_free(a.meta);
  }
};

GstStructure* copy_or_null(const GstStructure* s) { return s ? gst_structure_copy(s) : nullptr; }

GstPadProbeReturn at_source(GstPad*, GstPadProbeInfo* info, gpointer data) {
  GstBuffer* b = GST_PAD_PROBE_INFO_BUFFER(info);
  if (const GstStructure* s = gst_buffer_get_projtrack_meta(b))
    static_cast<Seen*>(data)->source[GST_BUFFER_PTS(b)] = gst_structure_copy(s);
  return GST_PAD_PROBE_OK;
}

void at_sink(GstElement*, GstBuffer* b, GstPad* pad, gpointer data) {
  GstCaps* caps = gst_pad_get_current_caps(pad);
  GstVideoInfo info;
  gst_video_info_from_caps(&info, caps);
  gst_caps_unref(caps);
  Seen::AtSink a{GST_BUFFER_PTS(b),
                 GST_VIDEO_INFO_WIDTH(&info),
                 GST_VIDEO_INFO_HEIGHT(&info),
                 copy_or_null(gst_buffer_get_projtrack_meta(b)),
                 {}};
  gpointer state = nullptr;
  while (GstMeta* m = gst_buffer_iterate_meta_filtered(b, &state,
                                                       GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE))
    a.rois.push_back(*reinterpret_cast<GstVideoRegionOfInterestMeta*>(m));
  static_cast<Seen*>(data)->sink.push_back(a);
}

// videotestsrc's ball (it starts at the frame's centre) at 640×480, tracked from the centre,
// then `after`, into a fakesink named "out".
void run(const std::string& after, Seen& seen, int frames = 4) {
  const std::string launch =
      "videotestsrc pattern=ball animation-mode=frames num-buffers=" + std::to_string(frames) +
      " ! video/x-raw,format=I420,width=640,height=480,framerate=30/1 ! projtrack name=t "
      "inner-point-x=320 inner-point-y=240 ! " +
      after + " ! fakesink name=out signal-handoffs=true sync=false";
  GError* error = nullptr;
  GstElement* p = gst_parse_launch(launch.c_str(), &error);
  ASSERT_NE(p, nullptr) << (error ? error->message : launch);
  GstElement* t = gst_bin_get_by_name(GST_BIN(p), "t");
  GstPad* src = gst_element_get_static_pad(t, "src");
  gst_pad_add_probe(src, GST_PAD_PROBE_TYPE_BUFFER, at_source, &seen, nullptr);
  gst_object_unref(src);
  gst_object_unref(t);
  GstElement* out = gst_bin_get_by_name(GST_BIN(p), "out");
  g_signal_connect(out, "handoff", G_CALLBACK(at_sink), &seen);
  gst_object_unref(out);
  ASSERT_NE(gst_element_set_state(p, GST_STATE_PLAYING), GST_STATE_CHANGE_FAILURE);
  GstBus* bus = gst_element_get_bus(p);
  GstMessage* m = gst_bus_timed_pop_filtered(
      bus, 20 * GST_SECOND, static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
  ASSERT_NE(m, nullptr) << "timed out";
  EXPECT_EQ(GST_MESSAGE_TYPE(m), GST_MESSAGE_EOS);
  gst_message_unref(m);
  gst_object_unref(bus);
  gst_element_set_state(p, GST_STATE_NULL);
  gst_object_unref(p);
  ASSERT_EQ(seen.source.size(), static_cast<size_t>(frames)) << "the ball is tracked";
  ASSERT_EQ(seen.sink.size(), static_cast<size_t>(frames));
}

int get_int(const GstStructure* s, const char* f) {
  int v = -12345;
  EXPECT_TRUE(gst_structure_get_int(s, f, &v)) << f;
  return v;
}
double get_double(const GstStructure* s, const char* f) {
  double v = NAN;
  EXPECT_TRUE(gst_structure_get_double(s, f, &v)) << f;
  return v;
}

// `after` (a frame of w × h) holds the features of `before` (640×480) scaled to it.
void expect_scaled(const GstStructure* before, const GstStructure* after, int w, int h) {
  const double sx = w / 640.0, sy = h / 480.0;
  GstProjtrackFeatures a, b;
  ASSERT_TRUE(gst_projtrack_features_read(before, &b));
  ASSERT_TRUE(gst_projtrack_features_read(after, &a));
  EXPECT_EQ(a.frame_width, w);
  EXPECT_EQ(a.frame_height, h);
  EXPECT_DOUBLE_EQ(a.centroid_x, (b.centroid_x + 0.5) * sx - 0.5);
  EXPECT_DOUBLE_EQ(a.centroid_y, (b.centroid_y + 0.5) * sy - 0.5);
  EXPECT_DOUBLE_EQ(a.area, b.area * sx * sy);
  EXPECT_EQ(a.x, static_cast<int>(std::floor(b.x * sx)));
  EXPECT_EQ(a.x + a.width, static_cast<int>(std::ceil((b.x + b.width) * sx)));
  EXPECT_EQ(a.y + a.height, static_cast<int>(std::ceil((b.y + b.height) * sy)));
  EXPECT_EQ(a.inner_point_x, static_cast<int>(std::floor((b.inner_point_x + 0.5) * sx)));
  EXPECT_EQ(a.track_id, b.track_id);
  EXPECT_STREQ(a.element, "t");
  EXPECT_STREQ(a.status, b.status);
  EXPECT_DOUBLE_EQ(a.depth, b.depth);  // relative to the frame: unchanged
  EXPECT_DOUBLE_EQ(a.position_x, b.position_x);
  ASSERT_EQ(gst_projtrack_outline_n_polygons(after), gst_projtrack_outline_n_polygons(before));
  ASSERT_GE(gst_projtrack_outline_n_polygons(after), 1u);
  int bx = 0, by = 0, ax = 0, ay = 0;
  for (guint i = 0; gst_projtrack_outline_vertex(before, 0, i, &bx, &by); ++i) {
    ASSERT_TRUE(gst_projtrack_outline_vertex(after, 0, i, &ax, &ay));
    EXPECT_EQ(ax, static_cast<int>(std::floor((bx + 0.5) * sx)));
    EXPECT_EQ(ay, static_cast<int>(std::floor((by + 0.5) * sy)));
  }
}

TEST(Meta, ScaledByVideoscaleToTheFrameThatCarriesIt) {
  for (auto [w, h] : {std::pair{320, 240}, std::pair{1280, 720}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    Seen seen;
    run("videoconvert ! videoscale ! video/x-raw,width=" + std::to_string(w) +
            ",height=" + std::to_string(h),
        seen);
    for (const Seen::AtSink& a : seen.sink) {
      ASSERT_EQ(a.width, w);
      ASSERT_NE(a.meta, nullptr) << "the meta survives";
      const GstStructure* before = seen.source.at(a.pts);
      expect_scaled(before, a.meta, w, h);
      // GStreamer's ROI meta: its box scaled by its own transform, its id the track's.
      ASSERT_EQ(a.rois.size(), 1u);
      EXPECT_EQ(a.rois[0].id, get_int(before, "track-id"));
      EXPECT_NEAR(a.rois[0].x, get_int(a.meta, "x"), 1);
    }
  }
}

TEST(Meta, CopiedThroughTeeQueueAndBufferCopies) {
  Seen seen;
  run("tee name=split split. ! queue ! fakesink split. ! queue ! videoconvert ! "
      "video/x-raw,format=RGB",  // the same size: copied (videoconvert calls the scale transform)
      seen);
  for (const Seen::AtSink& a : seen.sink) {
    ASSERT_NE(a.meta, nullptr);
    EXPECT_TRUE(gst_structure_is_equal(a.meta, seen.source.at(a.pts)));
  }
  // A copy of a buffer (what a writable map of a shared buffer makes) keeps it.
  GstBuffer* b = gst_buffer_new();
  GstStructure* features = gst_structure_copy(seen.source.begin()->second);
  GstCustomMeta* m = gst_buffer_add_custom_meta(b, GST_PROJTRACK_META_NAME);
  ASSERT_NE(m, nullptr) << "registered by the plugin";
  gst_structure_foreach(
      features,
      [](GQuark f, const GValue* v, gpointer s) -> gboolean {
        gst_structure_id_set_value(static_cast<GstStructure*>(s), f, v);
        return TRUE;
      },
      gst_custom_meta_get_structure(m));
  GstBuffer* copy = gst_buffer_copy(b);
  const GstStructure* copied = gst_buffer_get_projtrack_meta(copy);
  ASSERT_NE(copied, nullptr);
  EXPECT_EQ(get_double(copied, "area"), get_double(features, "area"));
  gst_structure_free(features);
  gst_buffer_unref(copy);
  gst_buffer_unref(b);
}

// GStreamer 1.22's videoflip calls no meta transform (GstVideoFilter's default keeps only metas
// tagged "video" alone), nor does videocrop when it copies: a meta of a frame's geometry is
// dropped there, ours and the ROI meta alike, rather than carried over wrong.
TEST(Meta, DroppedRatherThanWrongByVideoflipAndVideocrop) {
  for (const char* after : {"videoflip video-direction=90r", "videoflip video-direction=horiz",
                            "videocrop left=100 top=50"}) {
    SCOPED_TRACE(after);
    Seen seen;
    run(after, seen, 2);
    for (const Seen::AtSink& a : seen.sink) {
      EXPECT_EQ(a.meta, nullptr);
      EXPECT_TRUE(a.rois.empty());
    }
  }
}

// Two projtrack elements in a row: at the sink, both metas (the header's iterator), each with its
// element's name and a track id of its own, which the ROI metas' ids are.
TEST(Identity, EachElementItsOwnMetaRoiIdAndTrackId) {
  GstElement* p = gst_parse_launch(
      "videotestsrc pattern=ball animation-mode=frames num-buffers=1 ! "
      "video/x-raw,width=320,height=240 ! projtrack name=first inner-point-x=160 "
      "inner-point-y=120 ! projtrack name=second inner-point-x=160 inner-point-y=120 ! "
      "fakesink name=out signal-handoffs=true",
      nullptr);
  ASSERT_NE(p, nullptr);
  struct Found {
    std::set<std::string> elements;
    std::set<int> track_ids, roi_ids;
  } found;
  GstElement* out = gst_bin_get_by_name(GST_BIN(p), "out");
  g_signal_connect(out, "handoff",
                   G_CALLBACK(+[](GstElement*, GstBuffer* b, GstPad*, gpointer data) {
                     auto* f = static_cast<Found*>(data);
                     gpointer state = nullptr;
                     while (const GstStructure* s = gst_buffer_iterate_projtrack_meta(b, &state)) {
                       f->elements.insert(gst_structure_get_string(s, "element"));
                       int id = 0;
                       gst_structure_get_int(s, "track-id", &id);
                       f->track_ids.insert(id);
                     }
                     state = nullptr;
                     while (GstMeta* m = gst_buffer_iterate_meta_filtered(
                                b, &state, GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE))
                       f->roi_ids.insert(reinterpret_cast<GstVideoRegionOfInterestMeta*>(m)->id);
                   }),
                   &found);
  gst_object_unref(out);
  gst_element_set_state(p, GST_STATE_PLAYING);
  GstBus* bus = gst_element_get_bus(p);
  gst_message_unref(gst_bus_timed_pop_filtered(
      bus, 10 * GST_SECOND, static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR)));
  gst_object_unref(bus);
  gst_element_set_state(p, GST_STATE_NULL);
  gst_object_unref(p);
  EXPECT_EQ(found.elements, (std::set<std::string>{"first", "second"}));
  EXPECT_EQ(found.track_ids.size(), 2u) << "unique per element";
  EXPECT_EQ(found.roi_ids, found.track_ids) << "the ROI meta's id is the track's";
  EXPECT_EQ(found.track_ids.count(0), 0u);
}

// A bright disc on a dark background, GRAY8.
GstBuffer* disc(int w, int h, int cx, int cy, int r) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      map.data[y * w + x] = (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r ? 220 : 40;
  gst_buffer_unmap(b, &map);
  return b;
}

// One frame through a harnessed projtrack: its message's structure (copied) and its meta.
struct Frame {
  GstStructure* message = nullptr;
  GstStructure* meta = nullptr;
  ~Frame() {
    if (message) gst_structure_free(message);
    if (meta) gst_structure_free(meta);
  }
};

void push(GstHarness* h, GstBus* bus, GstBuffer* in, int i, Frame& f) {
  GST_BUFFER_PTS(in) = i * GST_SECOND / 30;
  ASSERT_EQ(gst_harness_push(h, in), GST_FLOW_OK);
  GstBuffer* out = gst_harness_pull(h);
  f.meta = copy_or_null(gst_buffer_get_projtrack_meta(out));
  gst_buffer_unref(out);
  GstMessage* m = gst_bus_pop_filtered(bus, GST_MESSAGE_ELEMENT);
  ASSERT_NE(m, nullptr);
  f.message = gst_structure_copy(gst_message_get_structure(m));
  gst_message_unref(m);
}

TEST(Identity, ATrackIdNewOnEveryAcquisitionAndTheOutlineInMessageAndMeta) {
  GstHarness* h = gst_harness_new("projtrack");
  GstBus* bus = gst_bus_new();
  gst_element_set_bus(h->element, bus);
  gst_harness_set_src_caps_str(h, "video/x-raw,format=GRAY8,width=240,height=180,framerate=30/1");
  gst_util_set_object_arg(G_OBJECT(h->element), "acquisition", "manual");
  g_signal_emit_by_name(h->element, "track-point", 100, 90);
  std::vector<int> ids;
  std::vector<bool> acquired;
  for (int i = 0; i < 16; ++i) {
    if (i == 3) g_signal_emit_by_name(h->element, "track-point", 100, 90);  // a new track
    // Frames 6-12: the disc is gone (lost, then dropped); from 13 the user points again.
    if (i == 13) g_signal_emit_by_name(h->element, "track-point", 100, 90);
    const bool gone = i >= 6 && i < 13;
    Frame f;
    push(h, bus, disc(240, 180, gone ? -1000 : 100, 90, 30), i, f);
    int id = 0;
    gst_structure_get_int(f.message, "track-id", &id);
    ids.push_back(id);
    acquired.push_back(gst_structure_has_field(f.message, "acquired"));
    if (!gone) {
      ASSERT_NE(f.meta, nullptr) << i;
      EXPECT_EQ(get_int(f.meta, "track-id"), id);
      EXPECT_STREQ(gst_structure_get_string(f.meta, "element"), GST_OBJECT_NAME(h->element));
      // The outline: one compact polygon along the disc's border, the same in the message.
      EXPECT_TRUE(gst_value_compare(gst_structure_get_value(f.meta, "outline"),
                                    gst_structure_get_value(f.message, "outline")) ==
                  GST_VALUE_EQUAL);
      ASSERT_EQ(gst_projtrack_outline_n_polygons(f.meta), 1u);
      int x = 0, y = 0;
      guint n = 0;
      for (; gst_projtrack_outline_vertex(f.meta, 0, n, &x, &y); ++n)
        EXPECT_NEAR(std::hypot(x - 100, y - 90), 30, 3);
      EXPECT_GE(n, 8u);
      EXPECT_LE(n, 48u);
    }
  }
  EXPECT_GT(ids[0], 0);
  EXPECT_EQ(ids[1], ids[0]);
  EXPECT_NE(ids[3], ids[0]) << "a new track, a new id";
  EXPECT_TRUE(acquired[3]);
  EXPECT_EQ(ids[5], ids[3]);
  EXPECT_NE(ids[13], ids[3]);
  EXPECT_TRUE(acquired[13]);
  EXPECT_EQ(ids[15], ids[13]);
  gst_harness_teardown(h);
  gst_bus_set_flushing(bus, TRUE);
  gst_object_unref(bus);
}

}  // namespace
