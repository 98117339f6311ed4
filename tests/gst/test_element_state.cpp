// Clear errors and kept state: a malformed start-box or track-box is refused with a warning and a
// detail (the track in hand goes on); a box partly outside the picture is clipped, one outside it
// is not applied, extreme numbers do not overflow; a new resolution rescales the track and a new
// format keeps it; a flush restarts it from the seed given; GAP buffers pass untouched and do not
// count against it; each status says why in its own words.
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "harness.hpp"

namespace {

using projtrack::test::converted;
using projtrack::test::video_caps;

const auto* const kGst = ::testing::AddGlobalTestEnvironment(new projtrack::test::GstInit);

// A reddish disc on a grey-green wall (colours that the formats store differently), in `format`.
GstBuffer* disc(const char* format, int w, int h, double cx, double cy, double r) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h * 3, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool in = std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= r;
      guint8* p = map.data + (static_cast<gsize>(y) * w + x) * 3;
      p[0] = in ? 200 : 100;
      p[1] = in ? 60 : 120;
      p[2] = in ? 40 : 90;
    }
  gst_buffer_unmap(b, &map);
  if (std::string(format) == "RGB" && w % 4 == 0) return b;
  return converted(b, video_caps("RGB", w, h), video_caps(format, w, h));
}

struct Frame {
  std::string status, detail;
  std::vector<std::string> warnings;
  bool message = false, meta = false, acquired = false, gap = false;
  int track_id = 0;
  double cx = NAN, cy = NAN, depth = NAN, area = NAN;
  GstBuffer* out = nullptr;
  ~Frame() {
    if (out) gst_buffer_unref(out);
  }
};

class State : public projtrack::test::ProjtrackHarness {
 protected:
  void SetUp() override {
    ProjtrackHarness::SetUp();
    gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "manual");
    g_object_set(h_->element, "smoothing", FALSE, nullptr);
  }
  void push(Frame& f, GstBuffer* in) {
    f.out = push_next(in);
    f.meta = gst_buffer_get_video_region_of_interest_meta(f.out) != nullptr;
    f.gap = GST_BUFFER_FLAG_IS_SET(f.out, GST_BUFFER_FLAG_GAP);
    while (GstMessage* m = gst_bus_pop(bus_)) {
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
        const GstStructure* s = gst_message_get_structure(m);
        f.message = true;
        f.status = gst_structure_get_string(s, "status");
        if (const char* d = gst_structure_get_string(s, "detail")) f.detail = d;
        f.acquired = gst_structure_has_field(s, "acquired");
        gst_structure_get_int(s, "track-id", &f.track_id);
        gst_structure_get_double(s, "centroid-x", &f.cx);
        gst_structure_get_double(s, "centroid-y", &f.cy);
        gst_structure_get_double(s, "depth", &f.depth);
        gst_structure_get_double(s, "area", &f.area);
      } else if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_WARNING) {
        f.warnings.push_back(projtrack::test::warning_text(m));
      }
      gst_message_unref(m);
    }
  }
  // Starts tracking the disc of 160×120 I420 frames; its track id.
  int track_disc() {
    gst_harness_set_src_caps_str(h_, video_caps("I420", 160, 120).c_str());
    g_signal_emit_by_name(h_->element, "track-point", 70, 64);
    Frame f;
    push(f, disc("I420", 160, 120, 70, 64, 30));
    EXPECT_EQ(f.status, "ok") << f.detail;
    return f.track_id;
  }
};

TEST_F(State, MalformedBoxesAreRefusedWithAWarningAndTheTrackGoesOn) {
  const int id = track_disc();
  const struct {
    const char* start_box;  // or, when null, track-box with `box`
    int box[4];
    const char* says;
  } cases[] = {{"<1, 2, 3>", {}, "3 numbers"},
               {"<1, 2, 3, 4, 5>", {}, "5 numbers"},
               {"<1, 2, 3, 4, 5, 6, 7, 8>", {}, "8 numbers"},
               {"<10, 10, 0, 20>", {}, "<10, 10, 0, 20> refused"},
               {"<10, 10, -5, 20>", {}, "width and height must be at least 1"},
               {"<10, 10, 20, -2147483648>", {}, "at least 1"},
               {nullptr, {10, 10, 0, 20}, "track-box <10, 10, 0, 20> refused"},
               {nullptr, {10, 10, -40, -40}, "track-box"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.start_box ? c.start_box : c.says);
    if (c.start_box)
      gst_util_set_object_arg(G_OBJECT(h_->element), "start-box", c.start_box);
    else
      g_signal_emit_by_name(h_->element, "track-box", c.box[0], c.box[1], c.box[2], c.box[3]);
    Frame f;
    push(f, disc("I420", 160, 120, 70, 64, 30));
    ASSERT_EQ(f.warnings.size(), 1u);
    EXPECT_NE(f.warnings[0].find(c.says), std::string::npos) << f.warnings[0];
    EXPECT_NE(f.detail.find(c.says), std::string::npos) << f.detail;
    EXPECT_EQ(f.status, "ok");  // the track in hand goes on
    EXPECT_FALSE(f.acquired);
    EXPECT_EQ(f.track_id, id);
    Frame next;
    push(next, disc("I420", 160, 120, 70, 64, 30));
    EXPECT_TRUE(next.warnings.empty()) << "said once";
    EXPECT_TRUE(next.detail.empty()) << next.detail;
  }
}

TEST_F(State, ABoxPartlyOutsideThePictureIsClipped) {
  gst_harness_set_src_caps_str(h_, video_caps("I420", 160, 120).c_str());
  // Its centre lies far outside; its part in the picture holds the disc.
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-box", "<-1000, -1000, 1045, 1045>");
  Frame f;
  push(f, disc("I420", 160, 120, 22, 22, 16));
  EXPECT_EQ(f.status, "ok") << f.detail;
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_NEAR(f.cx, 21.5, 2.5);
  EXPECT_NEAR(f.cy, 21.5, 2.5);
}

TEST_F(State, ABoxOutsideThePictureIsNotAppliedAndNoNumberOverflows) {
  const int id = track_disc();
  for (const char* box : {"<2147483647, 0, 2, 2>", "<0, 2147483647, 2147483647, 2147483647>",
                          "<-2147483648, -2147483648, 2147483647, 2147483647>", "<160, 0, 5, 5>"}) {
    SCOPED_TRACE(box);
    gst_util_set_object_arg(G_OBJECT(h_->element), "start-box", box);
    Frame f;
    push(f, disc("I420", 160, 120, 70, 64, 30));
    ASSERT_EQ(f.warnings.size(), 1u);
    EXPECT_NE(f.warnings[0].find("outside the 160x120 picture"), std::string::npos)
        << f.warnings[0];
    EXPECT_NE(f.detail.find("not applied"), std::string::npos) << f.detail;
    EXPECT_EQ(f.status, "ok");
    EXPECT_EQ(f.track_id, id);
  }
  // The whole picture and more: clipped to it.
  gst_util_set_object_arg(G_OBJECT(h_->element), "start-box", "<0, 0, 2147483647, 2147483647>");
  Frame f;
  push(f, disc("I420", 160, 120, 70, 64, 30));
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_TRUE(f.acquired);
}

TEST_F(State, ANewResolutionRescalesTheTrack) {
  gst_harness_set_src_caps_str(h_, video_caps("I420", 320, 240).c_str());
  g_signal_emit_by_name(h_->element, "track-point", 150, 110);
  Frame first;
  for (int i = 0; i < 3; ++i) {
    Frame f;
    push(f, disc("I420", 320, 240, 150, 110, 40));
    ASSERT_EQ(f.status, "ok") << f.detail;
    first.track_id = f.track_id;
    first.depth = f.depth;
  }
  for (auto [w, h] : {std::pair{160, 120}, std::pair{640, 480}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    const double k = w / 320.0;
    gst_harness_set_src_caps_str(h_, video_caps("I420", w, h).c_str());
    for (int i = 0; i < 3; ++i) {
      Frame f;
      push(f, disc("I420", w, h, 150 * k, 110 * k, 40 * k));
      EXPECT_EQ(f.status, "ok") << "frame " << i << ": " << f.detail;
      EXPECT_FALSE(f.acquired);
      EXPECT_EQ(f.track_id, first.track_id);
      EXPECT_NEAR(f.cx, 150 * k - 0.5, 1.5);
      EXPECT_NEAR(f.depth, first.depth, 0.05) << "depth goes on";
    }
    // The point given follows, for a restart.
    int x = 0;
    g_object_get(h_->element, "inner-point-x", &x, nullptr);
    EXPECT_NEAR(x, 150 * k, k + 1);
  }
}

// A still object in view stays tracked when the format changes at the same size: the colours
// learned on the old format are learned anew (an I420 frame's colours, limited range, are not an
// RGB frame's; a gray frame has none).
TEST_F(State, ANewFormatKeepsTheTrackOfAStillObject) {
  const std::pair<const char*, const char*> changes[] = {
      {"I420", "RGB"}, {"I420", "GRAY8"}, {"I420", "BGRA"}, {"RGB", "I420"}, {"GRAY8", "NV12"}};
  for (auto [from, to] : changes) {
    SCOPED_TRACE(std::string(from) + " -> " + to);
    gst_harness_set_src_caps_str(h_, video_caps(from, 160, 120).c_str());
    g_signal_emit_by_name(h_->element, "track-point", 70, 64);
    int id = 0;
    for (int i = 0; i < 4; ++i) {
      Frame f;
      push(f, disc(from, 160, 120, 70, 64, 30));
      ASSERT_EQ(f.status, "ok") << f.detail;
      id = f.track_id;
    }
    gst_harness_set_src_caps_str(h_, video_caps(to, 160, 120).c_str());
    for (int i = 0; i < 10; ++i) {
      Frame f;
      push(f, disc(to, 160, 120, 70, 64, 30));
      EXPECT_EQ(f.status, "ok") << "frame " << i << ": " << f.detail;
      EXPECT_EQ(f.track_id, id);
      EXPECT_NEAR(f.cx, 69.5, 1.5);
    }
  }
}

// The flow model (object-model=flow) through the element: a box start, a moving disc in every
// chroma layout the element reads (planar, pairs, macro-pixels, packed RGB, gray), then a new
// resolution; each frame's message says where the disc is and how large, never a NaN.
TEST_F(State, TheFlowModelFollowsAMovingDiscInEveryLayoutAndThroughANewResolution) {
  for (const char* format : {"I420", "NV12", "YUY2", "RGB", "GRAY8"}) {
    SCOPED_TRACE(format);
    gst_util_set_object_arg(G_OBJECT(h_->element), "object-model", "flow");
    gst_harness_set_src_caps_str(h_, video_caps(format, 320, 240).c_str());
    g_signal_emit_by_name(h_->element, "track-box", 60, 70, 80, 80);
    for (int i = 0; i < 12; ++i) {
      Frame f;
      const double cx = 100 + 3 * i, cy = 110 + i;
      push(f, disc(format, 320, 240, cx, cy, 36));
      ASSERT_EQ(f.status, "ok") << "frame " << i << ": " << f.detail;
      EXPECT_NEAR(f.cx, cx - 0.5, 3) << "frame " << i;
      EXPECT_NEAR(f.cy, cy - 0.5, 3) << "frame " << i;
      EXPECT_NEAR(f.area / (M_PI * 36 * 36), 1, 0.2) << "frame " << i;
    }
    gst_harness_set_src_caps_str(h_, video_caps(format, 160, 120).c_str());
    for (int i = 12; i < 16; ++i) {
      Frame f;
      push(f, disc(format, 160, 120, (100 + 3 * i) / 2.0, (110 + i) / 2.0, 18));
      EXPECT_EQ(f.status, "ok") << "frame " << i << ": " << f.detail;
      EXPECT_NEAR(f.cx, (100 + 3 * i) / 2.0 - 0.5, 3) << "frame " << i;
    }
    g_signal_emit_by_name(h_->element, "reset", nullptr);
  }
}

// A flush is a seek: what follows is another moment. The track restarts from the point given (a
// new acquisition, a new id), or, with none, acquisition starts over.
TEST_F(State, AFlushingSeekRestartsTheTrack) {
  const int id = track_disc();
  const auto flush = [&] {
    EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_flush_start()));
    EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_flush_stop(TRUE)));
    GstSegment segment;
    gst_segment_init(&segment, GST_FORMAT_TIME);
    EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_segment(&segment)));
    while (GstEvent* e = gst_harness_try_pull_event(h_)) gst_event_unref(e);
  };
  flush();
  Frame seeded;
  push(seeded, disc("I420", 160, 120, 70, 64, 30));
  EXPECT_EQ(seeded.status, "ok");
  EXPECT_TRUE(seeded.acquired) << "restarted from the point given";
  EXPECT_NE(seeded.track_id, id);
  // Found by acquisition (the frame centre here), no point given: after a flush, searched again.
  g_signal_emit_by_name(h_->element, "reset");
  gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "center");
  Frame centre;
  push(centre, disc("I420", 160, 120, 80, 60, 30));
  ASSERT_EQ(centre.status, "ok");
  flush();
  // The picture after the seek: nothing at the centre. The old track does not carry on.
  Frame after;
  push(after, disc("I420", 160, 120, -1000, -1000, 1));
  EXPECT_EQ(after.status, "searching") << after.detail;
}

TEST_F(State, GapBuffersPassUntouchedAndDoNotCountAgainstTheTrack) {
  const int id = track_disc();
  g_object_set(h_->element, "draw", TRUE, nullptr);
  // Seven GAP buffers (six refused frames would drop a track), with content that is no picture.
  for (int i = 0; i < 7; ++i) {
    GstBuffer* gap = gst_buffer_new_allocate(nullptr, 160 * 120 * 3 / 2, nullptr);
    gst_buffer_memset(gap, 0, 128, 160 * 120 * 3 / 2);
    GST_BUFFER_FLAG_SET(gap, GST_BUFFER_FLAG_GAP);
    GstBuffer* reference = gst_buffer_copy_deep(gap);
    Frame f;
    push(f, gap);
    EXPECT_TRUE(f.gap) << "still a GAP buffer";
    EXPECT_FALSE(f.meta);
    EXPECT_FALSE(f.message);
    GstMapInfo a, b;
    gst_buffer_map(f.out, &a, GST_MAP_READ);
    gst_buffer_map(reference, &b, GST_MAP_READ);
    EXPECT_TRUE(a.size == b.size && memcmp(a.data, b.data, a.size) == 0) << "untouched";
    gst_buffer_unmap(f.out, &a);
    gst_buffer_unmap(reference, &b);
    gst_buffer_unref(reference);
  }
  Frame back;
  push(back, disc("I420", 160, 120, 70, 64, 30));
  EXPECT_EQ(back.status, "ok") << back.detail;
  EXPECT_FALSE(back.acquired);
  EXPECT_EQ(back.track_id, id);
}

// Each status says why in its own words: no two statuses share their detail, and none that is
// not over budget speaks of the budget.
TEST_F(State, EachStatusHasItsOwnDetail) {
  gst_harness_set_src_caps_str(h_, video_caps("I420", 160, 120).c_str());
  std::set<std::string> details;
  const auto expect_detail = [&](const char* status) {
    Frame f;
    push(f, disc("I420", 160, 120, 70, 64, 30));
    EXPECT_EQ(f.status, status) << f.detail;
    EXPECT_FALSE(f.detail.empty()) << status;
    EXPECT_EQ(f.detail.find("budget"), std::string::npos) << status << ": " << f.detail;
    EXPECT_TRUE(details.insert(f.detail).second) << status << " says what another said";
  };
  expect_detail("no-inner-point");
  gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "auto");
  expect_detail("searching");
  g_signal_emit_by_name(h_->element, "track-point", 150, 110);  // on the wall, by the border
  expect_detail("lost");
  g_object_set(h_->element, "edge-threshold-low", 200.0, nullptr);
  expect_detail("invalid-parameters");
}

}  // namespace
