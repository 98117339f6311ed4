// What the element's tests share: GStreamer set up once per test program, caps and frames in any
// format, byte comparisons, and a harnessed projtrack with a bus of its own (GstHarness has none).
#pragma once

#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace projtrack::test {

// gst_init() before the first test: ::testing::AddGlobalTestEnvironment(new GstInit).
struct GstInit : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
};

inline std::string video_caps(const char* format, int width, int height) {
  return "video/x-raw,format=" + std::string(format) + ",width=" + std::to_string(width) +
         ",height=" + std::to_string(height) + ",framerate=30/1";
}

// `in` (taken) converted by videoconvert from caps `from` to caps `to`.
inline GstBuffer* converted(GstBuffer* in, const std::string& from, const std::string& to) {
  GstHarness* c = gst_harness_new("videoconvert");
  gst_harness_set_src_caps_str(c, from.c_str());
  gst_harness_set_sink_caps_str(c, to.c_str());
  GstBuffer* out = gst_harness_push_and_pull(c, in);
  gst_harness_teardown(c);
  return out;
}

inline bool same_bytes(GstBuffer* a, GstBuffer* b) {
  GstMapInfo ma, mb;
  gst_buffer_map(a, &ma, GST_MAP_READ);
  gst_buffer_map(b, &mb, GST_MAP_READ);
  const bool same = ma.size == mb.size && std::memcmp(ma.data, mb.data, ma.size) == 0;
  gst_buffer_unmap(a, &ma);
  gst_buffer_unmap(b, &mb);
  return same;
}

// A GRAY8 frame (rows of `width` bytes): a bright disc of radius r around (cx, cy) on a dark
// background.
inline GstBuffer* gray_disc(int width, int height, int cx, int cy, int r) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(width) * height, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const long long dx = x - cx, dy = y - cy;
      map.data[static_cast<gsize>(y) * width + x] = dx * dx + dy * dy <= 1LL * r * r ? 220 : 40;
    }
  gst_buffer_unmap(b, &map);
  return b;
}

// The text of an element warning message.
inline std::string warning_text(GstMessage* m) {
  GError* e = nullptr;
  gst_message_parse_warning(m, &e, nullptr);
  std::string text = e ? e->message : "";
  if (e) g_error_free(e);
  return text;
}

// A projtrack in a GstHarness, with a bus to read its messages from.
class ProjtrackHarness : public ::testing::Test {
 protected:
  void SetUp() override {
    h_ = gst_harness_new("projtrack");
    ASSERT_NE(h_, nullptr) << "is GST_PLUGIN_PATH set to the build's gst folder?";
    bus_ = gst_bus_new();
    gst_element_set_bus(h_->element, bus_);
  }
  void TearDown() override {
    gst_harness_teardown(h_);
    // Queued messages hold the element: drop them, or element and bus keep each other alive.
    gst_bus_set_flushing(bus_, TRUE);
    gst_object_unref(bus_);
  }
  // Pushes `in` (taken) stamped with the next frame's time; the output buffer (the caller's).
  GstBuffer* push_next(GstBuffer* in) {
    GST_BUFFER_PTS(in) = pts_;
    GST_BUFFER_DURATION(in) = GST_SECOND / 30;
    pts_ += GST_SECOND / 30;
    EXPECT_EQ(gst_harness_push(h_, in), GST_FLOW_OK);
    return gst_harness_pull(h_);
  }
  GstHarness* h_ = nullptr;
  GstBus* bus_ = nullptr;
  GstClockTime pts_ = 0;
};

}  // namespace projtrack::test
