// Several objects at once (issue 44): start-boxes and start-points, the add-box, add-point and
// remove-object signals, max-objects, click-adds and alpha-ids, each object's ROI meta, projtrack
// meta and message with its id; malformed lists and refused starts warned of on the bus, never a
// crash; the single track beside the objects as it always was. Frames: two bright discs on a
// dark GRAY8 (or BGRA) picture, moving a pixel a frame.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/navigation.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "gstprojtrackmeta.h"
#include "harness.hpp"

namespace {

using projtrack::test::warning_text;

const auto* const kGstInit = ::testing::AddGlobalTestEnvironment(new projtrack::test::GstInit);

constexpr int kWidth = 240, kHeight = 180, kRadius = 20;

// Disc centres on frame `i`: one on the left moving right, one on the right moving down.
struct Discs {
  int x1, y1, x2, y2;
};
Discs discs_at(int i) { return {60 + i, 90, 170, 80 + i}; }

GstBuffer* two_discs(const Discs& d) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, kWidth * kHeight, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool in =
          std::hypot(x - d.x1, y - d.y1) <= kRadius || std::hypot(x - d.x2, y - d.y2) <= kRadius;
      map.data[y * kWidth + x] = in ? 220 : 40;
    }
  gst_buffer_unmap(b, &map);
  return b;
}

std::string text_of(const GstStructure* s) {
  gchar* t = gst_structure_to_string(s);
  std::string out = t;
  g_free(t);
  return out;
}

class Objects : public projtrack::test::ProjtrackHarness {
 protected:
  void SetUp() override {
    ProjtrackHarness::SetUp();
    gst_harness_set_src_caps_str(h_, projtrack::test::video_caps("GRAY8", kWidth, kHeight).c_str());
  }
  // Pushes frame `frame_` (the discs where they are on it) and drops the output.
  void push_frame() { gst_buffer_unref(push_next(two_discs(discs_at(frame_++)))); }
  GstBuffer* push_kept() { return push_next(two_discs(discs_at(frame_++))); }
  // The projtrack messages posted since the last call, and the warnings' texts.
  std::vector<GstStructure*> messages() {
    std::vector<GstStructure*> out;
    while (GstMessage* m = gst_bus_pop_filtered(
               bus_, static_cast<GstMessageType>(GST_MESSAGE_ELEMENT | GST_MESSAGE_WARNING))) {
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_WARNING)
        warnings_.push_back(warning_text(m));
      else if (gst_message_has_name(m, "projtrack"))
        out.push_back(gst_structure_copy(gst_message_get_structure(m)));
      gst_message_unref(m);
    }
    return out;
  }
  // Drains the bus: the warnings posted since the last call, joined.
  std::string warnings() {
    for (GstStructure* s : messages()) gst_structure_free(s);
    std::string all;
    for (const std::string& w : warnings_) all += w + "\n";
    warnings_.clear();
    return all;
  }
  // The messages since the last call by their `id` (-1: none, the single track's).
  std::map<int, std::vector<std::string>> by_id() {
    std::map<int, std::vector<std::string>> out;
    for (GstStructure* s : messages()) {
      gint id = -1;
      gst_structure_get_int(s, "id", &id);
      out[id].push_back(text_of(s));
      gst_structure_free(s);
    }
    return out;
  }
  int add_box(int x, int y, int w, int h) {
    gint id = -1;
    g_signal_emit_by_name(h_->element, "add-box", x, y, w, h, &id);
    return id;
  }
  int add_point(int x, int y) {
    gint id = -1;
    g_signal_emit_by_name(h_->element, "add-point", x, y, &id);
    return id;
  }
  bool remove(int id) {
    gboolean removed = FALSE;
    g_signal_emit_by_name(h_->element, "remove-object", id, &removed);
    return removed;
  }
  std::string property_text(const char* name) {
    GValue v = G_VALUE_INIT;
    g_value_init(&v, GST_TYPE_ARRAY);
    g_object_get_property(G_OBJECT(h_->element), name, &v);
    gchar* t = gst_value_serialize(&v);
    std::string out = t;
    g_free(t);
    g_value_unset(&v);
    return out;
  }
  int frame_ = 0;
  std::vector<std::string> warnings_;
};

// What one object's metas on a buffer say: ROI id → (ROI box centre, projtrack meta's id).
struct ObjectMetas {
  double roi_cx = 0, roi_cy = 0;
  int meta_id = -1, param_id = -1;
  double centroid_x = 0, centroid_y = 0;
};

std::map<int, ObjectMetas> metas_of(GstBuffer* b) {
  std::map<int, ObjectMetas> out;
  gpointer state = nullptr;
  while (GstMeta* m = gst_buffer_iterate_meta_filtered(
             b, &state, GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE)) {
    auto* roi = reinterpret_cast<GstVideoRegionOfInterestMeta*>(m);
    ObjectMetas& o = out[roi->id];
    o.roi_cx = roi->x + roi->w / 2.0;
    o.roi_cy = roi->y + roi->h / 2.0;
    if (GstStructure* p = gst_video_region_of_interest_meta_get_param(roi, "projtrack"))
      gst_structure_get_int(p, "id", &o.param_id);
  }
  state = nullptr;
  while (const GstStructure* s = gst_buffer_iterate_projtrack_meta(b, &state)) {
    GstProjtrackFeatures f;
    EXPECT_TRUE(gst_projtrack_features_read(s, &f)) << text_of(s);
    if (f.id == 0) continue;  // the single track's
    out[f.id].meta_id = f.id;
    out[f.id].centroid_x = f.centroid_x;
    out[f.id].centroid_y = f.centroid_y;
  }
  return out;
}

double field(const std::string& message, const char* name) {
  GstStructure* s = gst_structure_from_string(message.c_str(), nullptr);
  gdouble v = NAN;
  if (s) gst_structure_get_double(s, name, &v);
  if (s) gst_structure_free(s);
  return v;
}

TEST_F(Objects, TwoStartBoxesEachGetTheirIdInMetasAndMessages) {
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<145,55,50,50>>");
  EXPECT_EQ(property_text("start-boxes"),
            "< (array)< (int)35, (int)65, (int)50, (int)50 >, (array)< (int)145, (int)55, (int)50, "
            "(int)50 > >");
  for (int i = 0; i < 5; ++i) {
    const Discs d = discs_at(frame_);
    GstBuffer* out = push_kept();
    const std::map<int, ObjectMetas> metas = metas_of(out);
    gst_buffer_unref(out);
    ASSERT_EQ(metas.size(), 2u) << "frame " << i;
    ASSERT_TRUE(metas.count(1) && metas.count(2)) << "frame " << i;
    EXPECT_EQ(metas.at(1).meta_id, 1);
    EXPECT_EQ(metas.at(1).param_id, 1);
    EXPECT_EQ(metas.at(2).param_id, 2);
    EXPECT_NEAR(metas.at(1).centroid_x, d.x1, 2.0);
    EXPECT_NEAR(metas.at(2).centroid_y, d.y2, 2.0);
    EXPECT_NEAR(metas.at(1).roi_cx, d.x1, 3.0);
    EXPECT_NEAR(metas.at(2).roi_cy, d.y2, 3.0);
    // One message per object, none from the single track (no seed: it waits beside them).
    std::map<int, std::vector<std::string>> messages = by_id();
    ASSERT_EQ(messages.size(), 2u) << "frame " << i;
    ASSERT_EQ(messages[1].size(), 1u);
    ASSERT_EQ(messages[2].size(), 1u);
    EXPECT_NEAR(field(messages[1][0], "centroid-x"), d.x1, 2.0) << messages[1][0];
    EXPECT_NEAR(field(messages[2][0], "centroid-y"), d.y2, 2.0) << messages[2][0];
    EXPECT_NE(messages[2][0].find("status=(string)ok"), std::string::npos) << messages[2][0];
  }
  EXPECT_EQ(warnings(), "");
}

TEST_F(Objects, StartPointsAndTheSingleTrackBeside) {
  g_object_set(h_->element, "inner-point-x", 60, "inner-point-y", 90, nullptr);
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-points", "<<170,80>>");
  EXPECT_EQ(property_text("start-points"), "< (array)< (int)170, (int)80 > >");
  push_frame();
  push_frame();
  std::map<int, std::vector<std::string>> messages = by_id();
  // The single track's messages as they always were: no id, a track-id.
  ASSERT_EQ(messages[-1].size(), 2u);
  EXPECT_NE(messages[-1][1].find("track-id"), std::string::npos);
  EXPECT_NEAR(field(messages[-1][1], "centroid-x"), 61, 2.0);
  ASSERT_EQ(messages[1].size(), 2u);
  EXPECT_NEAR(field(messages[1][1], "centroid-y"), 81, 2.0);
}

// Before caps there is no frame to check a start against: refused, and said why.
TEST(ObjectsWithoutCaps, AreRefused) {
  GstHarness* h = gst_harness_new("projtrack");
  GstBus* bus = gst_bus_new();
  gst_element_set_bus(h->element, bus);
  gint id = -1;
  g_signal_emit_by_name(h->element, "add-box", 10, 10, 50, 50, &id);
  EXPECT_EQ(id, 0);
  GstMessage* m = gst_bus_pop_filtered(bus, GST_MESSAGE_WARNING);
  ASSERT_NE(m, nullptr);
  EXPECT_NE(warning_text(m).find("no video yet"), std::string::npos) << warning_text(m);
  gst_message_unref(m);
  gst_harness_teardown(h);
  gst_bus_set_flushing(bus, TRUE);
  gst_object_unref(bus);
}

TEST_F(Objects, SignalsAddAndRemoveObjects) {
  push_frame();
  EXPECT_EQ(add_box(35 + frame_, 65, 50, 50), 1);
  EXPECT_EQ(add_point(170, 80 + frame_), 2);
  push_frame();
  std::map<int, std::vector<std::string>> messages = by_id();
  EXPECT_EQ(messages[1].size(), 1u);
  EXPECT_EQ(messages[2].size(), 1u);
  EXPECT_TRUE(remove(1));
  push_frame();
  messages = by_id();
  EXPECT_EQ(messages.count(1), 0u);
  EXPECT_EQ(messages[2].size(), 1u);
  GstBuffer* out = push_kept();
  EXPECT_EQ(metas_of(out).count(1), 0u);
  EXPECT_EQ(metas_of(out).count(2), 1u);
  gst_buffer_unref(out);
  EXPECT_EQ(warnings(), "");
  EXPECT_FALSE(remove(1));
  EXPECT_FALSE(remove(99));
  const std::string w = warnings();
  EXPECT_NE(w.find("no object of id 1"), std::string::npos) << w;
  EXPECT_NE(w.find("no object of id 99"), std::string::npos) << w;
  // An id is never given again: the next object is 3.
  EXPECT_EQ(add_box(35 + frame_, 65, 50, 50), 3);
}

TEST_F(Objects, RefusedStartsAreWarnedOfAndReturnZero) {
  push_frame();
  EXPECT_EQ(add_box(1000, 1000, 10, 10), 0);
  EXPECT_NE(warnings().find("add-box <1000, 1000, 10, 10> refused"), std::string::npos);
  EXPECT_EQ(add_box(50, 50, 0, 20), 0);
  EXPECT_NE(warnings().find("is empty"), std::string::npos);
  EXPECT_EQ(add_point(-3, 20), 0);
  EXPECT_NE(warnings().find("outside"), std::string::npos);
  const int id = add_point(60 + frame_, 90);
  EXPECT_EQ(id, 1);
  push_frame();
  EXPECT_EQ(add_point(60 + frame_, 92), 0) << "the object is followed already";
  EXPECT_NE(warnings().find("object 1 is there already"), std::string::npos);
  // A list's start refused when it is applied: the others are followed.
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<900,10,5,5>>");
  push_frame();
  // The list restarts the objects: object 1 is dropped, the box's object is new (ids go on).
  std::map<int, std::vector<std::string>> messages = by_id();
  EXPECT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[2].size(), 1u);
  const std::string w = warnings();
  EXPECT_NE(w.find("start-boxes entry <900, 10, 5, 5> refused"), std::string::npos) << w;
}

TEST_F(Objects, MalformedListsAreRefusedAndNamed) {
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>>");
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<1,2,3>>");
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-points", "<<1,2,3>>");
  // Not integers: GStreamer refuses to read them (the property keeps its value).
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<a,b,c,d>>");
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<1.5,2,3,4>>");
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<1,2,3,4>");
  EXPECT_EQ(property_text("start-boxes"), "< (array)< (int)35, (int)65, (int)50, (int)50 > >");
  EXPECT_EQ(property_text("start-points"), "<  >");
  push_frame();
  EXPECT_EQ(by_id()[1].size(), 1u) << "the list in hand goes on";
  const std::string w = warnings();
  EXPECT_NE(w.find("start-boxes refused: entry 2 <1, 2, 3> has 3 numbers, not the 4"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("start-points refused: entry 1 <1, 2, 3> has 3 numbers"), std::string::npos)
      << w;
}

TEST_F(Objects, MaxObjectsIsEnforced) {
  g_object_set(h_->element, "max-objects", 1u, nullptr);
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<145,55,50,50>>");
  push_frame();
  std::string w = warnings();
  EXPECT_NE(w.find("start-boxes entry <145, 55, 50, 50> refused: already following 1 objects, "
                   "max-objects is 1"),
            std::string::npos)
      << w;
  push_frame();
  EXPECT_EQ(by_id().size(), 1u);
  EXPECT_EQ(add_point(170, 80 + frame_), 0);
  EXPECT_NE(warnings().find("max-objects is 1"), std::string::npos);
  g_object_set(h_->element, "max-objects", 2u, nullptr);
  EXPECT_EQ(add_point(170, 80 + frame_), 2);
}

TEST_F(Objects, AClickAddsWithClickAdds) {
  push_frame();
  g_object_set(h_->element, "click-adds", TRUE, nullptr);
  ASSERT_TRUE(
      gst_harness_push_upstream_event(h_, gst_navigation_event_new_mouse_button_press(
                                              1, 170, 80 + frame_, GST_NAVIGATION_MODIFIER_NONE)));
  gint x = 0;
  g_object_get(h_->element, "inner-point-x", &x, nullptr);
  EXPECT_EQ(x, -1) << "the single track is left alone";
  warnings();
  push_frame();
  std::map<int, std::vector<std::string>> messages = by_id();
  ASSERT_EQ(messages[1].size(), 1u);
  EXPECT_NEAR(field(messages[1][0], "centroid-y"), 80 + frame_ - 1, 2.0) << messages[1][0];
  // A second click on the same object is refused: it is followed already.
  ASSERT_TRUE(
      gst_harness_push_upstream_event(h_, gst_navigation_event_new_mouse_button_press(
                                              1, 170, 80 + frame_, GST_NAVIGATION_MODIFIER_NONE)));
  EXPECT_NE(warnings().find("is there already"), std::string::npos);
}

TEST_F(Objects, UpdatesOnChangeAppliesPerObject) {
  gst_util_set_object_arg(G_OBJECT(h_->element), "updates", "on-change");
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<145,55,50,50>>");
  push_frame();
  std::map<int, std::vector<std::string>> messages = by_id();
  EXPECT_EQ(messages[1].size(), 1u);  // acquired
  EXPECT_EQ(messages[2].size(), 1u);
  for (int i = 0; i < 3; ++i) push_frame();
  EXPECT_EQ(by_id().size(), 0u) << "nothing changed";
}

// A flush is a seek: the objects start anew from the lists (new ids), and one added by a signal
// is dropped with the moment it was added in.
TEST_F(Objects, AFlushRestartsTheObjectsFromTheLists) {
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-points", "<<60,90>>");
  push_frame();
  EXPECT_EQ(add_point(170, 80 + frame_), 2);
  push_frame();
  EXPECT_EQ(by_id().size(), 2u);
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_flush_start()));
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_flush_stop(TRUE)));
  GstSegment segment;
  gst_segment_init(&segment, GST_FORMAT_TIME);
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_segment(&segment)));
  frame_ = 0;
  push_frame();
  std::map<int, std::vector<std::string>> messages = by_id();
  EXPECT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[3].size(), 1u) << "the list's point, with a new id";
}

// A bus sync handler runs in the streaming thread: adding an object from it must not wait for the
// frame that posted the message (the element posts after releasing its locks).
TEST_F(Objects, AnObjectCanBeAddedFromABusSyncHandler) {
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-points", "<<60,90>>");
  struct Added {
    GstElement* element;
    int id = -1;
    int y = 0;
  } added{h_->element, -1, 0};
  gst_bus_set_sync_handler(
      bus_,
      [](GstBus*, GstMessage* m, gpointer data) {
        auto* a = static_cast<Added*>(data);
        if (a->id < 0 && gst_message_has_name(m, "projtrack"))
          g_signal_emit_by_name(a->element, "add-point", 170, a->y, &a->id);
        return GST_BUS_PASS;
      },
      &added, nullptr);
  added.y = 80 + frame_;
  push_frame();
  EXPECT_EQ(added.id, 2);
  push_frame();
  gst_bus_set_sync_handler(bus_, nullptr, nullptr, nullptr);
  EXPECT_EQ(by_id()[2].size(), 1u);
}

}  // namespace

namespace {

// The same two discs in BGRA, for the alpha and the overlay.
class ObjectsBgra : public Objects {
 protected:
  void SetUp() override {
    ProjtrackHarness::SetUp();
    gst_harness_set_src_caps_str(h_, projtrack::test::video_caps("BGRA", kWidth, kHeight).c_str());
  }
  GstBuffer* push_bgra() {
    GstBuffer* bgra = projtrack::test::converted(
        two_discs(discs_at(frame_++)), projtrack::test::video_caps("GRAY8", kWidth, kHeight),
        projtrack::test::video_caps("BGRA", kWidth, kHeight));
    return push_next(bgra);
  }
};

// The 4 bytes (B, G, R, A) of pixel (x, y) of a BGRA buffer.
std::array<int, 4> bgra_at(GstBuffer* b, int x, int y) {
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_READ);
  const guint8* p = map.data + (static_cast<gsize>(y) * kWidth + x) * 4;
  const std::array<int, 4> out{p[0], p[1], p[2], p[3]};
  gst_buffer_unmap(b, &map);
  return out;
}

TEST_F(ObjectsBgra, AlphaIdsChoosesWhichObjectsAreCutOut) {
  g_object_set(h_->element, "alpha-mask", TRUE, nullptr);
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<145,55,50,50>>");
  Discs d = discs_at(frame_);
  GstBuffer* out = push_bgra();
  EXPECT_EQ(bgra_at(out, d.x1, d.y1)[3], 255) << "every object by default";
  EXPECT_EQ(bgra_at(out, d.x2, d.y2)[3], 255);
  EXPECT_EQ(bgra_at(out, 5, 5)[3], 0);
  gst_buffer_unref(out);
  gst_util_set_object_arg(G_OBJECT(h_->element), "alpha-ids", "<2>");
  d = discs_at(frame_);
  out = push_bgra();
  EXPECT_EQ(bgra_at(out, d.x1, d.y1)[3], 0) << "object 1 is not chosen";
  EXPECT_EQ(bgra_at(out, d.x2, d.y2)[3], 255);
  gst_buffer_unref(out);
}

// Each object's box in its own colour (object 1's is (0, 160, 255), object 2's (255, 0, 255)).
TEST_F(ObjectsBgra, TheOverlayDrawsEachObjectInItsColour) {
  g_object_set(h_->element, "draw", TRUE, nullptr);
  gst_util_set_object_arg(G_OBJECT(h_->element), "draw-flags", "box");
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-boxes", "<<35,65,50,50>,<145,55,50,50>>");
  GstBuffer* out = push_bgra();
  gpointer state = nullptr;
  int seen = 0;
  while (GstMeta* m = gst_buffer_iterate_meta_filtered(
             out, &state, GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE)) {
    auto* roi = reinterpret_cast<GstVideoRegionOfInterestMeta*>(m);
    const std::array<int, 4> left = bgra_at(out, roi->x, roi->y + roi->h / 2);
    const std::array<int, 3> bgr{left[0], left[1], left[2]};
    const std::array<int, 3> expected =
        roi->id == 1 ? std::array<int, 3>{255, 160, 0} : std::array<int, 3>{255, 0, 255};
    EXPECT_EQ(bgr, expected) << "object " << roi->id;
    ++seen;
  }
  EXPECT_EQ(seen, 2);
  gst_buffer_unref(out);
}

}  // namespace
