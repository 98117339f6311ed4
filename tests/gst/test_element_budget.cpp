// Bounded work through the element (issue 16): the max-work property, over-budget frames and
// their messages, settings refused up front, and a frame in progress stopped by a state change to
// NULL or by a flush. What is asserted is statuses and work, never a time: a stop that did not
// work would show as a frame that ends `ok` (or as a test that never ends).
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

struct GstEnvironment : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
};
const auto* const kGstEnvironment = ::testing::AddGlobalTestEnvironment(new GstEnvironment);

std::string caps(int w, int h) {
  return "video/x-raw,format=GRAY8,width=" + std::to_string(w) + ",height=" + std::to_string(h) +
         ",framerate=30/1";
}

// A bright disc on a dark background.
GstBuffer* disc(int w, int h) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      map.data[y * w + x] = std::hypot(x - w / 2, y - h / 2) <= h / 4 ? 220 : 40;
  gst_buffer_unmap(b, &map);
  return b;
}

// White 1-px dots on black, `share` of the pixels, fresh for every `seed`.
GstBuffer* dots(int w, int h, double share, unsigned seed) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (gsize i = 0; i < map.size; ++i) map.data[i] = u(rng) < share ? 255 : 0;
  gst_buffer_unmap(b, &map);
  return b;
}

GstBuffer* uniform(int w, int h) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h, nullptr);
  gst_buffer_memset(b, 0, 128, static_cast<gsize>(w) * h);
  return b;
}

struct Message {
  std::string status, detail;
  guint64 work = 0;
  bool has_work = false, has_centroid = false;
};

Message parse(const GstStructure* s) {
  Message m;
  if (const char* v = gst_structure_get_string(s, "status")) m.status = v;
  if (const char* v = gst_structure_get_string(s, "detail")) m.detail = v;
  m.has_work = gst_structure_get_uint64(s, "work", &m.work);
  m.has_centroid = gst_structure_has_field(s, "centroid-x");
  return m;
}

class Budget : public ::testing::Test {
 protected:
  void start(const std::string& props, int w, int h) {
    h_ = gst_harness_new_parse(("projtrack name=t " + props).c_str());
    ASSERT_NE(h_, nullptr) << "is GST_PLUGIN_PATH set to the build's gst folder?";
    element_ = gst_bin_get_by_name(GST_BIN(h_->element), "t");
    bus_ = gst_bus_new();
    gst_element_set_bus(element_, bus_);
    gst_harness_set_src_caps_str(h_, caps(w, h).c_str());
  }
  void TearDown() override {
    if (!h_) return;
    gst_harness_teardown(h_);
    gst_bus_set_flushing(bus_, TRUE);
    gst_object_unref(bus_);
    gst_object_unref(element_);
  }
  // Pushes one frame; its messages (and whether the buffer came out with a ROI meta).
  std::vector<Message> push(GstBuffer* in, bool* meta = nullptr) {
    EXPECT_EQ(gst_harness_push(h_, in), GST_FLOW_OK);
    GstBuffer* out = gst_harness_pull(h_);
    if (meta) *meta = gst_buffer_get_video_region_of_interest_meta(out) != nullptr;
    gst_buffer_unref(out);
    return messages();
  }
  std::vector<Message> messages(std::vector<std::string>* warnings = nullptr) {
    std::vector<Message> out;
    while (GstMessage* m = gst_bus_pop(bus_)) {
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
        out.push_back(parse(gst_message_get_structure(m)));
      } else if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_WARNING && warnings) {
        GError* e = nullptr;
        gst_message_parse_warning(m, &e, nullptr);
        warnings->push_back(e->message);
        g_error_free(e);
      }
      gst_message_unref(m);
    }
    return out;
  }
  GstHarness* h_ = nullptr;
  GstElement* element_ = nullptr;
  GstBus* bus_ = nullptr;
};

TEST_F(Budget, EveryMessageSaysItsWorkAndMaxWorkIsAProperty) {
  start("inner-point-x=80 inner-point-y=60 acquisition=manual", 160, 120);
  double max_work = -1;
  g_object_get(element_, "max-work", &max_work, nullptr);
  EXPECT_GT(max_work, 0) << "a default limit";
  const auto m = push(disc(160, 120));
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].status, "ok");
  ASSERT_TRUE(m[0].has_work);
  EXPECT_GT(m[0].work, 0u);
}

// Fresh random dots as the edge map, with pixel-filling and automatic acquisition: every seed's
// fill leaks to half the frame, and thirteen of them pass the budget. Once motion can be compared
// (from the second frame), each frame ends over budget, reported as such, without a ROI meta, and
// the next frame searches again; with no limit (max-work=0) every seed is tried. The budget is 8 ×
// the frame's pixels: max-work 8 × 640 × 480 ÷ 1.5 megapixels (what a smaller frame counts as).
TEST_F(Budget, AFrameThatRunsOutSaysSoAndTheNextOnesGoOn) {
  constexpr int kW = 640, kH = 480;
  start("object-model=edges method=pixel-filling edge-detector=input max-work=1.5625", kW, kH);
  const auto first = push(dots(kW, kH, 0.15, 100));
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].status, "searching") << first[0].detail;
  int over = 0;
  for (unsigned i = 0; i < 4; ++i) {
    bool meta = true;
    const auto m = push(dots(kW, kH, 0.15, i), &meta);
    ASSERT_EQ(m.size(), 1u);
    if (m[0].status == "over-budget") {
      ++over;
      EXPECT_FALSE(meta);
      EXPECT_NE(m[0].detail.find("budget"), std::string::npos) << m[0].detail;
      EXPECT_LE(m[0].work, static_cast<guint64>(8.5 * kW * kH)) << "8 × the pixels";
    }
  }
  EXPECT_EQ(over, 4);
  g_object_set(element_, "max-work", 0.0, nullptr);
  const auto m = push(dots(kW, kH, 0.15, 9));
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].status, "searching") << m[0].detail;
  EXPECT_GT(m[0].work, static_cast<guint64>(8.5 * kW * kH)) << "more than the limit would allow";
}

TEST_F(Budget, SettingsThatCanNeverFitAreRefusedAtOnceWithAWarning) {
  start(
      "object-model=edges method=recursive-ray-casting rays=1024 recursion=2 acquisition=manual "
      "inner-point-x=80 inner-point-y=60",
      160, 120);
  std::vector<std::string> warnings;
  gst_harness_push(h_, disc(160, 120));
  gst_buffer_unref(gst_harness_pull(h_));
  const auto m = messages(&warnings);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].status, "invalid-parameters");
  EXPECT_NE(m[0].detail.find("work units"), std::string::npos) << m[0].detail;
  EXPECT_EQ(m[0].work, 0u) << "refused before any work";
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("work units"), std::string::npos) << warnings[0];
}

// A frame that would run for minutes: no limit, a million rays per cast on a uniform 1080p frame
// (every ray crosses it), up to a thousand iterations.
const char* const kHuge =
    "object-model=edges method=recursive-ray-casting rays=1024 recursion=2 max-iterations=1000 "
    "convergence=0 max-work=0 acquisition=manual inner-point-x=640 inner-point-y=360";

// Waits until a buffer is in the element's chain function (its stream lock held: a state change
// to READY has to wait for it to leave).
struct Entered {
  std::mutex m;
  std::condition_variable cv;
  bool entered = false;
  static GstPadProbeReturn probe(GstPad*, GstPadProbeInfo*, gpointer data) {
    auto* e = static_cast<Entered*>(data);
    std::lock_guard<std::mutex> lock(e->m);
    e->entered = true;
    e->cv.notify_all();
    return GST_PAD_PROBE_OK;
  }
  void wait() {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return entered; });
  }
};

TEST(Stop, SetStateNullDuringAHugeFrameInterruptsIt) {
  constexpr int kW = 1920, kH = 1080;
  const std::string launch = "appsrc name=src format=time caps=\"" + caps(kW, kH) +
                             "\" ! projtrack name=t " + kHuge + " ! fakesink sync=false";
  GstElement* p = gst_parse_launch(launch.c_str(), nullptr);
  ASSERT_NE(p, nullptr);
  gst_pipeline_set_auto_flush_bus(GST_PIPELINE(p), FALSE);  // keep the messages past NULL
  GstElement* src = gst_bin_get_by_name(GST_BIN(p), "src");
  GstElement* t = gst_bin_get_by_name(GST_BIN(p), "t");
  Entered entered;
  GstPad* sink = gst_element_get_static_pad(t, "sink");
  gst_pad_add_probe(sink, GST_PAD_PROBE_TYPE_BUFFER, &Entered::probe, &entered, nullptr);
  gst_object_unref(sink);
  GstBus* bus = gst_element_get_bus(p);
  ASSERT_NE(gst_element_set_state(p, GST_STATE_PLAYING), GST_STATE_CHANGE_FAILURE);
  GstFlowReturn ret = GST_FLOW_ERROR;
  GstBuffer* frame = uniform(kW, kH);
  g_signal_emit_by_name(src, "push-buffer", frame, &ret);
  gst_buffer_unref(frame);
  ASSERT_EQ(ret, GST_FLOW_OK);
  entered.wait();
  // Without the interruption this would wait for the whole frame.
  EXPECT_EQ(gst_element_set_state(p, GST_STATE_NULL), GST_STATE_CHANGE_SUCCESS);
  std::vector<Message> ms;
  while (GstMessage* m = gst_bus_pop_filtered(bus, GST_MESSAGE_ELEMENT)) {
    if (gst_message_has_name(m, "projtrack")) ms.push_back(parse(gst_message_get_structure(m)));
    gst_message_unref(m);
  }
  ASSERT_EQ(ms.size(), 1u) << "the frame passed through with a message";
  EXPECT_EQ(ms[0].status, "interrupted") << ms[0].detail;
  EXPECT_NE(ms[0].detail.find("stopped from outside"), std::string::npos) << ms[0].detail;
  EXPECT_EQ(ms[0].detail.find("budget"), std::string::npos) << "no budget ran out";
  // One cast alone is a million rays of hundreds of steps each.
  EXPECT_LT(ms[0].work, 1000000000u);
  gst_object_unref(bus);
  gst_object_unref(t);
  gst_object_unref(src);
  gst_object_unref(p);
}

// A flush (a seek) stops the frame in progress too; after the flush the element tracks again.
TEST_F(Budget, AFlushInterruptsAHugeFrameAndTrackingGoesOn) {
  constexpr int kW = 1280, kH = 720;
  start(kHuge, kW, kH);
  Entered entered;
  GstPad* sink = gst_element_get_static_pad(element_, "sink");
  gst_pad_add_probe(sink, GST_PAD_PROBE_TYPE_BUFFER, &Entered::probe, &entered, nullptr);
  gst_object_unref(sink);
  GstFlowReturn pushed = GST_FLOW_OK;
  std::thread streaming([&] { pushed = gst_harness_push(h_, uniform(kW, kH)); });
  entered.wait();
  gst_harness_push_event(h_, gst_event_new_flush_start());
  streaming.join();
  EXPECT_EQ(pushed, GST_FLOW_FLUSHING) << "the frame ended while the element was flushing";
  auto m = messages();
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].status, "interrupted") << m[0].detail;
  EXPECT_EQ(m[0].detail.find("budget"), std::string::npos) << m[0].detail;
  gst_harness_push_event(h_, gst_event_new_flush_stop(TRUE));
  GstSegment segment;
  gst_segment_init(&segment, GST_FORMAT_TIME);
  gst_harness_push_event(h_, gst_event_new_segment(&segment));
  // Cheap settings again: the flag is down, the frame is measured.
  g_object_set(element_, "rays", 8u, "recursion", 2u, "max-iterations", 3u, "max-work", 8.0,
               "inner-point-x", kW / 2, "inner-point-y", kH / 2, nullptr);
  m = push(disc(kW, kH));
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].status, "ok") << m[0].detail;
}

}  // namespace
