// The gestures through the element: the message's and the ROI meta's `gesture` field says push,
// press and release on the frames they complete, and a new track while pressed releases.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness.hpp"
#include "scene.hpp"
#include "sequence.hpp"

namespace {

struct GstEnvironment : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
};
const auto* const kGstEnvironment = ::testing::AddGlobalTestEnvironment(new GstEnvironment);

namespace synthetic = projtrack::synthetic;

// What one frame reported: the message's gesture (empty: none), the ROI meta's, the depth.
struct Frame {
  std::string message_gesture, meta_gesture;
  double depth = 0;
};

std::string gesture_of(const GstStructure* s) {
  const char* g = s ? gst_structure_get_string(s, "gesture") : nullptr;
  return g ? g : "";
}

class Gestures : public projtrack::test::ProjtrackHarness {
 protected:
  void SetUp() override {
    ProjtrackHarness::SetUp();
    gst_harness_set_src_caps_str(h_,
                                 "video/x-raw,format=GRAY8,width=640,height=480,framerate=30/1");
  }
  // The sphere at (x, 240) scaled by `scale` as frame `i`: what the element reported.
  Frame push(int i, double x, double scale) {
    const synthetic::Scene s =
        synthetic::make_scene(synthetic::frame_at(synthetic::Object::Sphere, x, 240, i, scale), {});
    GstBuffer* in = gst_buffer_new_memdup(s.image.data, s.image.total());
    GST_BUFFER_PTS(in) = i * GST_SECOND / 30;
    GST_BUFFER_DURATION(in) = GST_SECOND / 30;
    EXPECT_EQ(gst_harness_push(h_, in), GST_FLOW_OK);
    GstBuffer* out = gst_harness_pull(h_);
    Frame f;
    if (auto* meta = gst_buffer_get_video_region_of_interest_meta(out))
      f.meta_gesture = gesture_of(gst_video_region_of_interest_meta_get_param(meta, "projtrack"));
    gst_buffer_unref(out);
    while (GstMessage* m = gst_bus_pop_filtered(bus_, GST_MESSAGE_ELEMENT)) {
      const GstStructure* st = gst_message_get_structure(m);
      f.message_gesture = gesture_of(st);
      gst_structure_get_double(st, "depth", &f.depth);
      gst_message_unref(m);
    }
    return f;
  }
};

// Forward over 0.2 s from `start`, held `hold` s, back over 0.2 s: the sphere's extra scale.
double press(double t, double start, double hold, double depth) {
  const double u = t - start;
  if (u <= 0 || u >= hold + 0.4) return 0.0;
  const double w = u < 0.2 ? u / 0.2 : u < 0.2 + hold ? 1.0 : 1 - (u - 0.2 - hold) / 0.2;
  return depth * (1 - std::cos(M_PI * w)) / 2;
}

// A push: +`depth` as a raised cosine over 0.3 s from `start`.
double click(double t, double start, double depth) {
  const double u = (t - start) / 0.3;
  return u <= 0 || u >= 1 ? 0.0 : depth * (1 - std::cos(2 * M_PI * u)) / 2;
}

TEST_F(Gestures, APressADragAReleaseThenAClickInTheMessageAndTheMeta) {
  g_object_set(h_->element, "inner-point-x", 300, "inner-point-y", 240, nullptr);
  std::vector<std::string> said;
  for (int i = 0; i < 150; ++i) {
    const double t = i / 30.0;
    // Pressed at 1.5 s, dragged 120 px right while held, back at 3.3 s; a click at 4.2 s.
    const double drag = 120 * std::clamp((t - 1.7) / 1.4, 0.0, 1.0);
    const Frame f = push(i, 300 + drag, 1 + press(t, 1.5, 1.4, 0.3) + click(t, 4.2, 0.3));
    EXPECT_EQ(f.meta_gesture, f.message_gesture) << "frame " << i;
    if (f.message_gesture.empty()) continue;
    said.push_back(f.message_gesture);
    if (f.message_gesture == "press") {
      EXPECT_NEAR(t, 1.7, 0.4);
    }
    if (f.message_gesture == "release") {
      EXPECT_NEAR(t, 3.4, 0.3);
    }
    if (f.message_gesture == "push") {
      EXPECT_NEAR(t, 4.35, 0.3);
    }
  }
  EXPECT_EQ(said, (std::vector<std::string>{"press", "release", "push"}));
}

TEST_F(Gestures, ANewTrackWhilePressedReleasesTheButton) {
  g_object_set(h_->element, "inner-point-x", 300, "inner-point-y", 240, nullptr);
  std::vector<std::string> said;
  for (int i = 0; i < 90; ++i) {
    if (i == 75)  // the user points at the object again: a new track
      g_object_set(h_->element, "inner-point-x", 305, "inner-point-y", 240, nullptr);
    const Frame f = push(i, 300, 1 + press(i / 30.0, 1.5, 5.0, 0.3));
    if (!f.message_gesture.empty()) said.push_back(f.message_gesture + "@" + std::to_string(i));
  }
  ASSERT_EQ(said.size(), 2u);
  EXPECT_EQ(said[0].substr(0, 6), "press@");
  EXPECT_EQ(said[1], "release@75");
}

TEST_F(Gestures, DepthIsTheObjectsShareOfTheFrame) {
  g_object_set(h_->element, "inner-point-x", 300, "inner-point-y", 240, "smoothing", FALSE,
               nullptr);
  for (int i = 0; i < 3; ++i) push(i, 300, 1.0);
  const synthetic::Scene s =
      synthetic::make_scene(synthetic::frame_at(synthetic::Object::Sphere, 300, 240, 3, 1.0), {});
  const Frame f = push(3, 300, 1.0);
  EXPECT_NEAR(f.depth, std::sqrt(s.true_area / (640.0 * 480)), 0.03 * f.depth);
}

}  // namespace
