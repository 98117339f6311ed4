// The element under every format, size, renegotiation, flush, state cycle, concurrent property
// change and extreme property value: each case must end in a defined outcome — one message per
// buffer, a known status, finite numbers — and never in a crash or a leak.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/navigation.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "harness.hpp"
#include "projtrack/method.hpp"

namespace {

using projtrack::kMethodCount;
using projtrack::kMethods;
using projtrack::Method;
using projtrack::method_name;

struct GstEnvironment : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
  // With GST_TRACERS=leaks the tracer reports leaked GStreamer objects here (test_element_leaks).
  void TearDown() override { gst_deinit(); }
};
const auto* const kGstEnvironment = ::testing::AddGlobalTestEnvironment(new GstEnvironment);

constexpr const char* kFormats[] = {"GRAY8", "I420", "YV12", "NV12", "NV21", "Y42B", "YUY2",
                                    "UYVY",  "Y444", "BGRx", "RGBx", "xRGB", "xBGR", "BGRA",
                                    "RGBA",  "ARGB", "ABGR", "BGR",  "RGB",  "AYUV", "A420"};

const std::set<std::string> kStatuses = {
    "ok",          "reached-border", "covers-frame",        "lost",
    "searching",   "no-inner-point", "inner-point-outside", "inner-point-on-edge",
    "empty-image", "invalid-image",  "invalid-parameters",  "over-budget",
    "interrupted"};

std::string caps_of(const char* format, int w, int h) {
  return "video/x-raw,format=" + std::string(format) + ",width=" + std::to_string(w) +
         ",height=" + std::to_string(h) + ",framerate=30/1";
}

// A bright disc filling a third of the frame on a dark background, in `format`.
GstBuffer* frame(const char* format, int w, int h) {
  const int stride = (w + 3) & ~3;
  GstBuffer* gray = gst_buffer_new_allocate(nullptr, static_cast<gsize>(stride) * h, nullptr);
  GstMapInfo map;
  gst_buffer_map(gray, &map, GST_MAP_WRITE);
  const double r = std::min(w, h) / 3.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < stride; ++x)
      map.data[y * stride + x] = std::hypot(x - w / 2.0, y - h / 2.0) <= r ? 220 : 40;
  gst_buffer_unmap(gray, &map);
  if (std::string(format) == "GRAY8") return gray;
  GstHarness* convert = gst_harness_new("videoconvert");
  gst_harness_set_src_caps_str(convert, caps_of("GRAY8", w, h).c_str());
  gst_harness_set_sink_caps_str(convert, caps_of(format, w, h).c_str());
  GstBuffer* out = gst_harness_push_and_pull(convert, gray);
  gst_harness_teardown(convert);
  return out;
}

// Every field of a projtrack message: a known status, finite doubles. Returns the status.
std::string check_message(GstMessage* m) {
  const GstStructure* s = gst_message_get_structure(m);
  EXPECT_STREQ(gst_structure_get_name(s), "projtrack");
  const char* status = gst_structure_get_string(s, "status");
  EXPECT_NE(status, nullptr);
  EXPECT_TRUE(status && kStatuses.count(status)) << (status ? status : "(none)");
  for (int i = 0; i < gst_structure_n_fields(s); ++i) {
    const char* name = gst_structure_nth_field_name(s, i);
    const GValue* v = gst_structure_get_value(s, name);
    if (G_VALUE_HOLDS_DOUBLE(v)) {
      EXPECT_TRUE(std::isfinite(g_value_get_double(v))) << name;
    }
  }
  return status ? status : "";
}

class Matrix : public projtrack::test::ProjtrackHarness {
 protected:
  // Pushes one buffer and returns the status of its message (checked).
  std::string push(GstBuffer* buf) {
    GST_BUFFER_PTS(buf) = pts_;
    GST_BUFFER_DURATION(buf) = GST_SECOND / 30;
    pts_ += GST_SECOND / 30;
    EXPECT_EQ(gst_harness_push(h_, buf), GST_FLOW_OK);
    GstBuffer* out = gst_harness_pull(h_);
    EXPECT_NE(out, nullptr);
    if (out) gst_buffer_unref(out);
    GstMessage* m = gst_bus_pop_filtered(bus_, GST_MESSAGE_ELEMENT);
    EXPECT_NE(m, nullptr) << "one message per buffer";
    if (!m) return "";
    const std::string status = check_message(m);
    gst_message_unref(m);
    return status;
  }
};

TEST_F(Matrix, EveryFormatAtEverySize) {
  const std::pair<int, int> sizes[] = {{1, 1},     {2, 2},       {3, 5},
                                       {641, 479}, {1920, 1080}, {4096, 2160}};
  int cases = 0;
  for (const char* format : kFormats) {
    for (auto [w, h] : sizes) {
      SCOPED_TRACE(std::string(format) + " " + std::to_string(w) + "x" + std::to_string(h));
      gst_harness_set_src_caps_str(h_, caps_of(format, w, h).c_str());
      g_object_set(h_->element, "inner-point-x", w / 2, "inner-point-y", h / 2, nullptr);
      const std::string status = push(frame(format, w, h));
      if (w >= 641) {
        EXPECT_EQ(status, "ok");  // the disc is found and measured
      }
      ++cases;
    }
  }
  std::cout << cases << " format x size cases\n";
}

TEST_F(Matrix, RenegotiationUpAndDownMidStream) {
  const struct {
    const char* format;
    int w, h;
  } steps[] = {{"I420", 320, 240}, {"BGRx", 1920, 1080}, {"GRAY8", 64, 48}, {"NV12", 641, 479},
               {"RGB", 1, 1},      {"Y444", 333, 222},   {"I420", 320, 240}};
  g_object_set(h_->element, "draw", TRUE, nullptr);
  for (const auto& s : steps) {
    gst_harness_set_src_caps_str(h_, caps_of(s.format, s.w, s.h).c_str());
    g_object_set(h_->element, "inner-point-x", s.w / 2, "inner-point-y", s.h / 2, nullptr);
    for (int i = 0; i < 3; ++i) {
      const std::string status = push(frame(s.format, s.w, s.h));
      if (s.w >= 64) {
        EXPECT_EQ(status, "ok") << s.format << ' ' << s.w;
      }
    }
  }
}

TEST_F(Matrix, FlushAndEos) {
  gst_harness_set_src_caps_str(h_, caps_of("I420", 160, 120).c_str());
  g_object_set(h_->element, "inner-point-x", 80, "inner-point-y", 60, nullptr);
  EXPECT_EQ(push(frame("I420", 160, 120)), "ok");
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_flush_start()));
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_flush_stop(TRUE)));
  GstSegment segment;
  gst_segment_init(&segment, GST_FORMAT_TIME);
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_segment(&segment)));
  pts_ = 0;
  EXPECT_EQ(push(frame("I420", 160, 120)), "ok");  // the track survives a flush
  EXPECT_TRUE(gst_harness_push_event(h_, gst_event_new_eos()));
  bool eos = false;
  while (GstEvent* e = gst_harness_try_pull_event(h_)) {
    eos |= GST_EVENT_TYPE(e) == GST_EVENT_EOS;
    gst_event_unref(e);
  }
  EXPECT_TRUE(eos);
}

TEST_F(Matrix, ExtremeInnerPoints) {
  gst_harness_set_src_caps_str(h_, caps_of("NV12", 160, 120).c_str());
  gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "manual");
  const std::pair<int, int> points[] = {{G_MAXINT, G_MAXINT}, {0, G_MAXINT}, {159, 119},
                                        {160, 120},           {0, 0},        {G_MAXINT, 0}};
  for (gboolean draw : {0, 1}) {
    g_object_set(h_->element, "draw", draw, nullptr);
    for (auto [x, y] : points) {
      g_object_set(h_->element, "inner-point-x", x, "inner-point-y", y, nullptr);
      push(frame("NV12", 160, 120));
    }
    // Clicks far outside and at negative coordinates are ignored; NaN coordinates too.
    for (double c : {-1e9, -1.0, 1e12, std::nan("")}) {
      gst_harness_push_upstream_event(
          h_, gst_navigation_event_new_mouse_button_press(1, c, c, GST_NAVIGATION_MODIFIER_NONE));
      push(frame("NV12", 160, 120));
    }
  }
}

TEST_F(Matrix, EveryNumericPropertyAtItsMinimumAndMaximum) {
  gst_harness_set_src_caps_str(h_, caps_of("GRAY8", 64, 48).c_str());
  guint n = 0;
  GParamSpec** specs = g_object_class_list_properties(G_OBJECT_GET_CLASS(h_->element), &n);
  int cases = 0;
  for (guint i = 0; i < n; ++i) {
    GParamSpec* p = specs[i];
    if (p->owner_type != G_OBJECT_TYPE(h_->element) || !(p->flags & G_PARAM_WRITABLE)) continue;
    GValue lo = G_VALUE_INIT, hi = G_VALUE_INIT, def = G_VALUE_INIT;
    g_value_init(&lo, p->value_type);
    g_value_init(&hi, p->value_type);
    g_value_init(&def, p->value_type);
    g_param_value_set_default(p, &def);
    if (G_IS_PARAM_SPEC_UINT(p)) {
      g_value_set_uint(&lo, G_PARAM_SPEC_UINT(p)->minimum);
      g_value_set_uint(&hi, G_PARAM_SPEC_UINT(p)->maximum);
    } else if (G_IS_PARAM_SPEC_INT(p)) {
      g_value_set_int(&lo, G_PARAM_SPEC_INT(p)->minimum);
      g_value_set_int(&hi, G_PARAM_SPEC_INT(p)->maximum);
    } else if (G_IS_PARAM_SPEC_DOUBLE(p)) {
      g_value_set_double(&lo, G_PARAM_SPEC_DOUBLE(p)->minimum);
      g_value_set_double(&hi, G_PARAM_SPEC_DOUBLE(p)->maximum);
    } else {
      continue;
    }
    for (const GValue* v : {&lo, &hi}) {
      // A fill and a ray method: between them, every parameter is read.
      for (Method m : {Method::GridFilling, Method::RasterizedRayCasting}) {
        const char* method = method_name(m).data();
        SCOPED_TRACE(std::string(p->name) + " = " + g_strdup_value_contents(v) + ", " + method);
        gst_util_set_object_arg(G_OBJECT(h_->element), "method", method);
        g_object_set_property(G_OBJECT(h_->element), p->name, v);
        g_object_set(h_->element, "inner-point-x", 32, "inner-point-y", 24, nullptr);
        push(frame("GRAY8", 64, 48));
        push(frame("GRAY8", 64, 48));
        ++cases;
      }
    }
    g_object_set_property(G_OBJECT(h_->element), p->name, &def);
    g_value_unset(&lo);
    g_value_unset(&hi);
    g_value_unset(&def);
  }
  g_free(specs);
  std::cout << cases << " property extremes\n";
  EXPECT_GT(cases, 40);
}

// start-box and track-box at the ends of their ranges, malformed, outside and around the picture:
// a defined status every time (sanitized builds: no overflow, no read outside the frame).
TEST_F(Matrix, StartBoxAndTrackBoxAtTheirExtremes) {
  gst_harness_set_src_caps_str(h_, caps_of("I420", 160, 120).c_str());
  gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "manual");
  const char* boxes[] = {"<>",
                         "<0, 0, 1, 1>",
                         "<159, 119, 1, 1>",
                         "<160, 120, 1, 1>",
                         "<2147483647, 0, 2, 2>",
                         "<0, 2147483647, 2, 2>",
                         "<2147483647, 2147483647, 2147483647, 2147483647>",
                         "<-2147483648, -2147483648, 2147483647, 2147483647>",
                         "<-2147483648, 0, 1, 1>",
                         "<0, 0, 2147483647, 2147483647>",
                         "<-1000, -1000, 1100, 1080>",
                         "<-1, -1, 2, 2>",
                         "<1, 2, 3>",
                         "<1, 2, 3, 4, 5>",
                         "<1, 2, 3, 4, 5, 6, 7, 8>",
                         "<10, 10, 0, 20>",
                         "<10, 10, -5, -5>",
                         "<0, 0, -2147483648, -2147483648>"};
  for (gboolean draw : {0, 1}) {
    g_object_set(h_->element, "draw", draw, "alpha-mask", draw, nullptr);
    for (const char* box : boxes) {
      SCOPED_TRACE(box);
      gst_util_set_object_arg(G_OBJECT(h_->element), "start-box", box);
      push(frame("I420", 160, 120));
      push(frame("I420", 160, 120));
    }
    for (const gint v : {G_MININT, -1, 0, 1, 159, 160, G_MAXINT})
      for (const gint size : {G_MININT, 0, 1, 80, G_MAXINT}) {
        SCOPED_TRACE("track-box " + std::to_string(v) + " " + std::to_string(size));
        g_signal_emit_by_name(h_->element, "track-box", v, v, size, size);
        push(frame("I420", 160, 120));
      }
  }
}

TEST_F(Matrix, PropertiesChangedFromAnotherThreadWhileBuffersFlow) {
  gst_harness_set_src_caps_str(h_, caps_of("I420", 160, 120).c_str());
  std::atomic<bool> done{false};
  std::thread poker([&] {
    std::mt19937 rng(4);
    const char* detectors[] = {"canny", "sobel", "input"};
    const char* acquisitions[] = {"manual", "center", "auto"};
    while (!done) {
      GObject* e = G_OBJECT(h_->element);
      switch (rng() % 8) {
        case 0:
          gst_util_set_object_arg(e, "method", kMethods[rng() % kMethodCount].nick);
          break;
        case 1:
          gst_util_set_object_arg(e, "edge-detector", detectors[rng() % 3]);
          break;
        case 2:
          gst_util_set_object_arg(e, "acquisition", acquisitions[rng() % 3]);
          break;
        case 3:
          g_object_set(e, "rays", 3u + rng() % 60, "grid-size", 1u + rng() % 40, "max-gap",
                       1u + rng() % 15, nullptr);
          break;
        case 4:
          g_object_set(e, "inner-point-x", int(rng() % 200) - 1, "inner-point-y",
                       int(rng() % 150) - 1, nullptr);
          break;
        case 5:
          g_object_set(e, "draw", gboolean(rng() % 2), "post-messages", TRUE, nullptr);
          break;
        case 6:
          g_object_set(e, "blur", guint(rng() % 4), "edge-threshold-low", double(rng() % 200),
                       nullptr);
          break;
        default: {
          gint x = 0;
          g_object_get(e, "inner-point-x", &x, nullptr);  // reads race with writes too
        }
      }
    }
  });
  for (int i = 0; i < 300; ++i) push(frame("I420", 160, 120));
  done = true;
  poker.join();
}

TEST(Cycles, HundredTimesNullToPlayingToNull) {
  int messages = 0;
  for (int i = 0; i < 100; ++i) {
    GstElement* pipe = gst_parse_launch(
        "videotestsrc pattern=ball num-buffers=3 ! video/x-raw,width=160,height=120 ! "
        "projtrack inner-point-x=80 inner-point-y=60 ! fakesink",
        nullptr);
    ASSERT_NE(pipe, nullptr);
    GstBus* bus = gst_element_get_bus(pipe);
    ASSERT_NE(gst_element_set_state(pipe, GST_STATE_PLAYING), GST_STATE_CHANGE_FAILURE);
    for (bool eos = false; !eos;) {
      GstMessage* m = gst_bus_timed_pop_filtered(
          bus, 10 * GST_SECOND,
          static_cast<GstMessageType>(GST_MESSAGE_ELEMENT | GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
      ASSERT_NE(m, nullptr) << "cycle " << i << " timed out";
      EXPECT_NE(GST_MESSAGE_TYPE(m), GST_MESSAGE_ERROR);
      eos = GST_MESSAGE_TYPE(m) != GST_MESSAGE_ELEMENT;
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
        EXPECT_EQ(check_message(m), "ok");
        ++messages;
      }
      gst_message_unref(m);
    }
    gst_element_set_state(pipe, GST_STATE_NULL);
    gst_object_unref(bus);
    gst_object_unref(pipe);
  }
  EXPECT_EQ(messages, 300);
}

long rss_kb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

// 10 000 frames of tracking with the overlay: after the first thousand, memory stays flat.
TEST_F(Matrix, LongRunMemoryIsSteady) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed memory: resident size grows anyway";
#endif
  gst_harness_set_src_caps_str(h_, caps_of("I420", 160, 120).c_str());
  g_object_set(h_->element, "inner-point-x", 80, "inner-point-y", 60, "draw", TRUE, nullptr);
  GstBuffer* input = frame("I420", 160, 120);
  long at_1000 = 0;
  for (int i = 0; i < 10000; ++i) {
    EXPECT_EQ(push(gst_buffer_copy_deep(input)), "ok");
    if (i == 999) at_1000 = rss_kb();
  }
  const long at_10000 = rss_kb();
  gst_buffer_unref(input);
  std::cout << "RSS after 1000 frames " << at_1000 << " kB, after 10000 " << at_10000 << " kB\n";
  EXPECT_LT(at_10000 - at_1000, 1024);
}

}  // namespace
