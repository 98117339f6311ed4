// Starting, stopping and reading a track from an app, and how often the element speaks: the
// track-point, track-box and reset action signals, start-box, current-inner-point-x/y, updates,
// conflicting settings reported at once, YUY2/UYVY read like the planar formats, properties
// driven by a GstController, and what gst-inspect-1.0 shows.
#include <gst/check/gstharness.h>
#include <gst/controller/gstdirectcontrolbinding.h>
#include <gst/controller/gstinterpolationcontrolsource.h>
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <regex>
#include <string>
#include <vector>

#include "harness.hpp"
#include "projtrack/method.hpp"

namespace {

const auto* const kGst = ::testing::AddGlobalTestEnvironment(new projtrack::test::GstInit);

constexpr int kW = 160, kH = 120, kCx = 70, kCy = 64, kRadius = 30;

std::string caps(const char* format) {
  return "video/x-raw,format=" + std::string(format) + ",width=" + std::to_string(kW) +
         ",height=" + std::to_string(kH) + ",framerate=30/1";
}

// A bright disc on a dark background, in `format` (videoconvert from GRAY8).
GstBuffer* disc(const char* format = "GRAY8") {
  GstBuffer* b = projtrack::test::gray_disc(kW, kH, kCx, kCy, kRadius);
  if (std::string(format) == "GRAY8") return b;
  return projtrack::test::converted(b, caps("GRAY8"), caps(format));
}

struct Frame {
  std::vector<GstStructure*> messages;  // the projtrack messages this frame posted
  std::vector<std::string> warnings;    // element warnings, their texts
  bool meta = false;                    // the buffer carries the ROI meta
  ~Frame() {
    for (GstStructure* s : messages) gst_structure_free(s);
  }
  std::string status() const {
    return messages.empty() ? "" : gst_structure_get_string(messages.back(), "status");
  }
  double get(const char* field) const {
    double v = NAN;
    if (!messages.empty()) gst_structure_get_double(messages.back(), field, &v);
    return v;
  }
};

class Control : public projtrack::test::ProjtrackHarness {
 protected:
  void SetUp() override {
    ProjtrackHarness::SetUp();
    gst_harness_set_src_caps_str(h_, caps("GRAY8").c_str());
    gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "manual");
  }
  void push(Frame& f, GstBuffer* in = nullptr) {
    GST_BUFFER_PTS(in ? in : (in = disc())) = pts_;
    pts_ += GST_SECOND / 30;
    ASSERT_EQ(gst_harness_push(h_, in), GST_FLOW_OK);
    GstBuffer* out = gst_harness_pull(h_);
    f.meta = gst_buffer_get_video_region_of_interest_meta(out) != nullptr;
    gst_buffer_unref(out);
    while (GstMessage* m = gst_bus_pop(bus_)) {
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT) {
        f.messages.push_back(gst_structure_copy(gst_message_get_structure(m)));
      } else if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_WARNING) {
        f.warnings.push_back(projtrack::test::warning_text(m));
      }
      gst_message_unref(m);
    }
  }
  int int_property(const char* name) {
    int v = 0;
    g_object_get(h_->element, name, &v, nullptr);
    return v;
  }
};

TEST_F(Control, TrackPointStartsInOneCallAndTheCurrentInnerPointFollowsTheObject) {
  Frame before;
  push(before);
  EXPECT_EQ(before.status(), "no-inner-point");
  EXPECT_EQ(int_property("current-inner-point-x"), -1);
  // Seeded off-centre, inside the disc: the tracker moves its inner point toward the middle.
  const int sx = kCx + kRadius / 2, sy = kCy;
  g_signal_emit_by_name(h_->element, "track-point", sx, sy);
  EXPECT_EQ(int_property("inner-point-x"), sx);  // the seed, as given
  EXPECT_EQ(int_property("inner-point-y"), sy);
  Frame f;
  push(f);
  EXPECT_EQ(f.status(), "ok");
  EXPECT_NEAR(f.get("centroid-x"), kCx, 1.0);
  const int cx = int_property("current-inner-point-x"), cy = int_property("current-inner-point-y");
  EXPECT_LT(std::hypot(cx - kCx, cy - kCy), std::hypot(sx - kCx, sy - kCy)) << cx << "," << cy;
  EXPECT_EQ(int_property("inner-point-x"), sx);  // still the seed
}

TEST_F(Control, TrackBoxAndStartBoxStartATrackAndResetStopsIt) {
  for (bool by_signal : {true, false}) {
    SCOPED_TRACE(by_signal ? "track-box" : "start-box");
    if (by_signal)
      g_signal_emit_by_name(h_->element, "track-box", kCx - 20, kCy - 20, 40, 40);
    else  // as gst-launch-1.0 sets it
      gst_util_set_object_arg(G_OBJECT(h_->element), "start-box", "<50, 44, 40, 40>");
    GValue box = G_VALUE_INIT;
    g_value_init(&box, GST_TYPE_ARRAY);
    g_object_get_property(G_OBJECT(h_->element), "start-box", &box);
    gchar* text = gst_value_serialize(&box);
    EXPECT_STREQ(text, "< (int)50, (int)44, (int)40, (int)40 >");
    g_free(text);
    g_value_unset(&box);
    EXPECT_EQ(int_property("inner-point-x"), -1);  // a box, not a point
    Frame f;
    push(f);
    EXPECT_EQ(f.status(), "ok");
    EXPECT_TRUE(f.meta);
    EXPECT_NEAR(f.get("centroid-x"), kCx, 1.5);
    EXPECT_NEAR(f.get("area"), M_PI * kRadius * kRadius, 0.15 * M_PI * kRadius * kRadius);
    EXPECT_GE(int_property("current-inner-point-x"), 0);

    g_signal_emit_by_name(h_->element, "reset");
    Frame stopped;
    push(stopped);
    EXPECT_EQ(stopped.status(), "no-inner-point");
    EXPECT_FALSE(stopped.meta);
    EXPECT_EQ(int_property("current-inner-point-x"), -1);
  }
}

TEST_F(Control, ABoxIsKeptAcrossARestart) {
  g_signal_emit_by_name(h_->element, "track-box", kCx - 20, kCy - 20, 40, 40);
  Frame f;
  push(f);
  ASSERT_EQ(f.status(), "ok");
  gst_harness_set_src_caps_str(h_, caps("I420").c_str());  // the track restarts from the box
  Frame again;
  push(again, disc("I420"));
  EXPECT_EQ(again.status(), "ok");
  EXPECT_NEAR(again.get("centroid-x"), kCx, 1.5);
}

TEST_F(Control, UpdatesEveryFrameOnChangeOrNone) {
  g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
  const struct {
    const char* updates;
    std::vector<size_t> messages;  // per frame: the first acquires, the fifth is after a reset
  } cases[] = {
      {"every-frame", {1, 1, 1, 1, 1}}, {"on-change", {1, 0, 0, 0, 1}}, {"none", {0, 0, 0, 0, 0}}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.updates);
    gst_util_set_object_arg(G_OBJECT(h_->element), "updates", c.updates);
    g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
    for (size_t i = 0; i < c.messages.size(); ++i) {
      if (i == 4) g_signal_emit_by_name(h_->element, "reset");
      Frame f;
      push(f);
      EXPECT_EQ(f.messages.size(), c.messages[i]) << "frame " << i;
      EXPECT_EQ(f.meta, i < 4);  // the meta, whatever the messages
    }
  }
  g_object_set(h_->element, "post-messages", FALSE, nullptr);
  gst_util_set_object_arg(G_OBJECT(h_->element), "updates", "every-frame");
  Frame quiet;
  push(quiet);
  EXPECT_TRUE(quiet.messages.empty());  // post-messages=false silences every mode
}

TEST_F(Control, ConflictingSettingsAreReportedAtOnceNotSearchedWith) {
  gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "auto");
  const struct {
    const char* model;
    const char* property;
    const char* value;
    const char* says;
  } cases[] = {{"edges", "rays", "1024", "rays^recursion"},
               {"appearance", "rays", "1024", "rays^recursion"},
               {"edges", "edge-threshold-low", "200", "edge-threshold-low 200"},
               {"appearance", "edge-threshold-low", "200", "edge-threshold-low 200"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.model) + " " + c.property);
    gst_util_set_object_arg(G_OBJECT(h_->element), "object-model", c.model);
    g_object_set(h_->element, "recursion", 4u, nullptr);
    gst_util_set_object_arg(G_OBJECT(h_->element), c.property, c.value);
    Frame first, second;
    push(first);
    EXPECT_EQ(first.status(), "invalid-parameters");  // not "searching"
    ASSERT_EQ(first.warnings.size(), 1u);
    EXPECT_NE(first.warnings[0].find(c.says), std::string::npos) << first.warnings[0];
    push(second);
    EXPECT_EQ(second.status(), "invalid-parameters");
    EXPECT_TRUE(second.warnings.empty());  // said once, not on every frame
    g_object_set(h_->element, "rays", 8u, "recursion", 2u, "edge-threshold-low", 50.0, nullptr);
    Frame fixed;
    push(fixed);
    EXPECT_NE(fixed.status(), "invalid-parameters");
    EXPECT_TRUE(fixed.warnings.empty());
  }
  // Sobel reads only the low threshold: no conflict.
  gst_util_set_object_arg(G_OBJECT(h_->element), "edge-detector", "sobel");
  g_object_set(h_->element, "edge-threshold-low", 200.0, nullptr);
  Frame sobel;
  push(sobel);
  EXPECT_NE(sobel.status(), "invalid-parameters");
}

TEST_F(Control, PackedYuvIsTrackedAsThePlanarFormats) {
  g_object_set(h_->element, "rays", 32u, nullptr);
  std::vector<double> centroid_x, area;
  for (const char* format : {"I420", "Y42B", "YUY2", "UYVY"}) {
    gst_harness_set_src_caps_str(h_, caps(format).c_str());
    g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
    Frame f;
    push(f, disc(format));
    ASSERT_EQ(f.status(), "ok") << format;
    centroid_x.push_back(f.get("centroid-x"));
    area.push_back(f.get("area"));
  }
  for (size_t i = 1; i < area.size(); ++i) {
    EXPECT_DOUBLE_EQ(centroid_x[i], centroid_x[0]);
    EXPECT_DOUBLE_EQ(area[i], area[0]);
  }
}

// A GstController drives a controllable property frame by frame (the element syncs it to each
// buffer's stream time): edge-threshold-low interpolated from 50 to 200 over a second, read back
// after each frame, and in effect: above edge-threshold-high (150) the settings conflict.
TEST_F(Control, AControllerDrivesAPropertyFrameByFrame) {
  g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
  GstControlSource* source = gst_interpolation_control_source_new();
  g_object_set(source, "mode", GST_INTERPOLATION_MODE_LINEAR, nullptr);
  gst_timed_value_control_source_set(GST_TIMED_VALUE_CONTROL_SOURCE(source), 0, 50.0);
  gst_timed_value_control_source_set(GST_TIMED_VALUE_CONTROL_SOURCE(source), GST_SECOND, 200.0);
  GstObject* element = GST_OBJECT(h_->element);
  ASSERT_TRUE(gst_object_add_control_binding(
      element, gst_direct_control_binding_new_absolute(element, "edge-threshold-low", source)));
  const struct {
    double low;
    const char* status;
  } expected[] = {{50, "ok"}, {100, "ok"}, {150, "ok"}, {200, "invalid-parameters"}};
  for (const auto& e : expected) {  // frames at 0, 1/3, 2/3 and 1 s
    Frame f;
    pts_ = static_cast<GstClockTime>(std::llround(e.low - 50)) * GST_SECOND / 150;
    push(f);
    double low = 0;
    g_object_get(h_->element, "edge-threshold-low", &low, nullptr);
    EXPECT_NEAR(low, e.low, 1e-6);
    EXPECT_EQ(f.status(), e.status) << "at " << e.low;
  }
  gst_object_unref(source);
}

// Every property flagged controllable takes a binding; the seeds, whose every setting restarts
// the track, are not controllable.
TEST_F(Control, ControllablePropertiesTakeABinding) {
  guint n = 0;
  GParamSpec** specs = g_object_class_list_properties(G_OBJECT_GET_CLASS(h_->element), &n);
  GstObject* element = GST_OBJECT(h_->element);
  int controllable = 0;
  for (guint i = 0; i < n; ++i) {
    if (!(specs[i]->flags & GST_PARAM_CONTROLLABLE)) continue;
    ++controllable;
    GstControlSource* source = gst_interpolation_control_source_new();
    GstControlBinding* b = gst_direct_control_binding_new(element, specs[i]->name, source);
    EXPECT_TRUE(gst_object_add_control_binding(element, b)) << specs[i]->name;
    gst_object_remove_control_binding(element, b);
    gst_object_unref(source);
  }
  g_free(specs);
  EXPECT_GE(controllable, 10);
  for (const char* seed : {"inner-point-x", "inner-point-y", "start-box"}) {
    GParamSpec* p = g_object_class_find_property(G_OBJECT_GET_CLASS(h_->element), seed);
    EXPECT_FALSE(p->flags & GST_PARAM_CONTROLLABLE) << seed;
  }
}

TEST(Inspect, PackageOriginContactAndBlurbsInAUsersWordsThatNameTheirMethods) {
  GstElementFactory* factory = gst_element_factory_find("projtrack");
  ASSERT_NE(factory, nullptr);
  // The author survives an install: a real address (-Dcontact) or none, never a placeholder.
  const std::string author = gst_element_factory_get_metadata(factory, "author");
  EXPECT_FALSE(author.empty());
  EXPECT_FALSE(
      std::regex_search(author, std::regex("example|noreply|localhost|invalid", std::regex::icase)))
      << author;
  // One line, as gst-inspect-1.0 lists elements; the details are in the documentation.
  const std::string description = gst_element_factory_get_metadata(factory, "description");
  EXPECT_LE(description.size(), 100u) << description;
  EXPECT_EQ(description.find('\n'), std::string::npos);
  EXPECT_NE(description.find("centroid"), std::string::npos) << description;
  const char* doc = gst_element_factory_get_metadata(factory, GST_ELEMENT_METADATA_DOC_URI);
  ASSERT_NE(doc, nullptr) << "no documentation URI";
  EXPECT_TRUE(std::regex_search(doc, std::regex("^(file|https?)://.*element"))) << doc;
  if (g_str_has_prefix(doc, "file://")) {  // a build from source: the installed page, which
    // outlives the source and build trees (meson installs docs/ there)
    EXPECT_TRUE(g_str_has_suffix(doc, "/doc/projtrack/element.md")) << doc;
    EXPECT_EQ(std::string(doc).find("/docs/"), std::string::npos) << doc;
  }
  GstPlugin* plugin = gst_plugin_feature_get_plugin(GST_PLUGIN_FEATURE(factory));
  EXPECT_STRNE(gst_plugin_get_origin(plugin), "Unknown package origin");
  EXPECT_EQ(std::string(gst_plugin_get_origin(plugin)).find("source tree"), std::string::npos);
  EXPECT_STRNE(gst_plugin_get_package(plugin), "");
  gst_object_unref(plugin);

  GstElement* e = gst_element_factory_create(factory, nullptr);
  guint n = 0;
  GParamSpec** specs = g_object_class_list_properties(G_OBJECT_GET_CLASS(e), &n);
  const std::regex nick("[a-z]+(-[a-z]+)*-(ray-casting|filling)");
  // The paper's notation: its symbols n (rays), y (recursion), m (block and grid size) alone or
  // in its methods' names ("n-ray-casting", "n^y", "m×m", "m-grid-filling", "n ray hits").
  const std::regex paper(
      "(^|[^A-Za-z0-9_])(n\\^y|[nm](-|\\^|\\*|×|x[0-9a-z]|$|[ ,.:;)])|"
      "[nmy] (ray|rays|hits|levels?|cells?|blocks?)\\b)");
  const auto in_a_users_words = [&](const std::string& text) {
    return !std::regex_search(text, paper);
  };
  ASSERT_FALSE(in_a_users_words("n-ray-casting: mean of n ray hits"));
  ASSERT_FALSE(in_a_users_words("Iterative n^y-ray-casting with m-rasterization"));
  ASSERT_FALSE(in_a_users_words("fill along a grid of m×m cells"));
  ASSERT_FALSE(in_a_users_words("the m of the grid"));
  ASSERT_FALSE(in_a_users_words("recast from every hit, y levels deep"));
  ASSERT_TRUE(in_a_users_words("rays to the power recursion, max-gap px, 3x3 box blur, my way"));
  ASSERT_TRUE(in_a_users_words("x, y and depth; inner-point-y"));
  int naming = 0;
  for (guint i = 0; i < n; ++i) {
    if (G_PARAM_SPEC_VALUE_TYPE(specs[i]) == G_TYPE_STRING) continue;  // name, GstObject's
    const std::string blurb = g_param_spec_get_blurb(specs[i]);
    EXPECT_TRUE(in_a_users_words(blurb)) << specs[i]->name << ": " << blurb;
    // A one-line summary, as gst-inspect-1.0 lists it; the detail is docs/element.md's.
    EXPECT_LE(blurb.size(), 100u) << specs[i]->name << ": " << blurb;
    EXPECT_EQ(blurb.find('\n'), std::string::npos) << specs[i]->name;
    if (G_IS_PARAM_SPEC_ENUM(specs[i])) {  // what gst-inspect-1.0 lists for each value
      const GEnumClass* values = G_PARAM_SPEC_ENUM(specs[i])->enum_class;
      for (guint v = 0; v < values->n_values; ++v)
        EXPECT_TRUE(in_a_users_words(values->values[v].value_name))
            << specs[i]->name << " " << values->values[v].value_nick << ": "
            << values->values[v].value_name;
    }
    for (std::sregex_iterator m(blurb.begin(), blurb.end(), nick), end; m != end; ++m) {
      EXPECT_TRUE(projtrack::method_from_name(m->str())) << specs[i]->name << ": " << m->str();
      ++naming;
    }
  }
  EXPECT_GE(naming, 8);  // the method-specific properties say which methods they tune
  g_free(specs);
  gst_object_unref(e);
  gst_object_unref(factory);
}

}  // namespace
