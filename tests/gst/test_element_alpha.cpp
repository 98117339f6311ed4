// The silhouette out as video: alpha-mask=true writes the object's silhouette into the alpha
// channel of every format that has one (opaque inside, transparent elsewhere), leaves the others
// and every format without the property untouched, and lets compositor cut the object out.
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "harness.hpp"

namespace {

using projtrack::test::converted;
using projtrack::test::same_bytes;
using projtrack::test::video_caps;

const auto* const kGst = ::testing::AddGlobalTestEnvironment(new projtrack::test::GstInit);

constexpr int kW = 160, kH = 120, kCx = 70, kCy = 64, kR = 30;

std::string caps(const char* format) { return video_caps(format, kW, kH); }

// A bright disc on a dark background, in `format` (videoconvert from GRAY8).
GstBuffer* disc(const char* format) {
  return converted(projtrack::test::gray_disc(kW, kH, kCx, kCy, kR), caps("GRAY8"), caps(format));
}

// The alpha of a frame in `format`: per pixel, and how many pixels are opaque.
struct Alpha {
  guint8 centre = 0, corner = 0;
  int opaque = 0, transparent = 0;
};

Alpha read_alpha(GstBuffer* b, const char* format) {
  GstVideoInfo info;
  GstCaps* c = gst_caps_from_string(caps(format).c_str());
  gst_video_info_from_caps(&info, c);
  gst_caps_unref(c);
  GstVideoFrame f;
  Alpha a;
  if (!gst_video_frame_map(&f, &info, b, GST_MAP_READ)) return a;
  const auto at = [&](int x, int y) {
    return static_cast<const guint8*>(GST_VIDEO_FRAME_COMP_DATA(
        &f, GST_VIDEO_COMP_A))[y * GST_VIDEO_FRAME_COMP_STRIDE(&f, GST_VIDEO_COMP_A) +
                               x * GST_VIDEO_FRAME_COMP_PSTRIDE(&f, GST_VIDEO_COMP_A)];
  };
  a.centre = at(kCx, kCy);
  a.corner = at(kW - 1, kH - 1);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      a.opaque += at(x, y) == 255;
      a.transparent += at(x, y) == 0;
    }
  gst_video_frame_unmap(&f);
  return a;
}

class AlphaMask : public projtrack::test::ProjtrackHarness {
 protected:
  void SetUp() override {
    ProjtrackHarness::SetUp();
    gst_util_set_object_arg(G_OBJECT(h_->element), "acquisition", "manual");
  }
  // `in` (kept) through the element; the output.
  GstBuffer* push(GstBuffer* in) { return push_next(gst_buffer_ref(in)); }
};

TEST_F(AlphaMask, TheSilhouetteIsTheAlphaOfEveryFormatWithOne) {
  for (const char* format : {"AYUV", "A420", "BGRA", "RGBA", "ARGB", "ABGR"}) {
    SCOPED_TRACE(format);
    gst_harness_set_src_caps_str(h_, caps(format).c_str());
    g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
    g_object_set(h_->element, "alpha-mask", TRUE, nullptr);
    GstBuffer* in = disc(format);
    GstBuffer* out = push(in);
    const Alpha a = read_alpha(out, format);
    EXPECT_EQ(a.centre, 255);
    EXPECT_EQ(a.corner, 0);
    EXPECT_EQ(a.opaque + a.transparent, kW * kH) << "only 0 and 255";
    EXPECT_NEAR(a.opaque, M_PI * kR * kR, 0.12 * M_PI * kR * kR) << "the disc's pixels";
    gst_buffer_unref(out);
    // No object: all transparent. Without the property: the frame is left as it came.
    g_signal_emit_by_name(h_->element, "reset");
    out = push(in);
    EXPECT_EQ(read_alpha(out, format).transparent, kW * kH);
    gst_buffer_unref(out);
    g_object_set(h_->element, "alpha-mask", FALSE, nullptr);
    g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
    GstBuffer* reference = gst_buffer_copy_deep(in);
    out = push(in);
    EXPECT_TRUE(same_bytes(out, reference));
    gst_buffer_unref(out);
    gst_buffer_unref(reference);
    gst_buffer_unref(in);
  }
}

TEST_F(AlphaMask, FormatsWithoutAlphaAreLeftAlone) {
  g_object_set(h_->element, "alpha-mask", TRUE, nullptr);
  for (const char* format : {"I420", "BGRx", "GRAY8"}) {
    SCOPED_TRACE(format);
    gst_harness_set_src_caps_str(h_, caps(format).c_str());
    g_signal_emit_by_name(h_->element, "track-point", kCx, kCy);
    GstBuffer* in = disc(format);
    GstBuffer* reference = gst_buffer_copy_deep(in);
    GstBuffer* out = push(in);
    EXPECT_TRUE(same_bytes(out, reference));
    gst_buffer_unref(out);
    gst_buffer_unref(reference);
    gst_buffer_unref(in);
  }
}

// compositor blends by alpha: the object over another picture. videotestsrc's ball (white, at
// the frame's centre on the first frame) over a red background: white where the ball is, red
// where projtrack's frame was black; without alpha-mask, black.
TEST(Compositor, CutsTheObjectOut) {
  for (bool alpha : {true, false}) {
    SCOPED_TRACE(alpha ? "alpha-mask=true" : "alpha-mask=false");
    const std::string launch =
        std::string(
            "compositor name=c ! videoconvert ! video/x-raw,format=RGB,width=160,height=120 ! ") +
        "fakesink name=out signal-handoffs=true  videotestsrc pattern=red num-buffers=1 ! "
        "video/x-raw,width=160,height=120 ! c.sink_0  videotestsrc pattern=ball num-buffers=1 ! "
        "video/x-raw,format=BGRA,width=160,height=120 ! projtrack inner-point-x=80 "
        "inner-point-y=60 alpha-mask=" +
        (alpha ? "true" : "false") + " ! c.sink_1";
    GstElement* p = gst_parse_launch(launch.c_str(), nullptr);
    ASSERT_NE(p, nullptr);
    struct Pixels {
      guint8 centre[3] = {}, corner[3] = {};
      int frames = 0;
    } px;
    GstElement* out = gst_bin_get_by_name(GST_BIN(p), "out");
    g_signal_connect(out, "handoff",
                     G_CALLBACK(+[](GstElement*, GstBuffer* b, GstPad*, gpointer data) {
                       auto* px = static_cast<Pixels*>(data);
                       GstMapInfo map;
                       gst_buffer_map(b, &map, GST_MAP_READ);
                       const int stride = (160 * 3 + 3) & ~3;
                       memcpy(px->centre, map.data + 60 * stride + 80 * 3, 3);
                       memcpy(px->corner, map.data + 5 * stride + 5 * 3, 3);
                       gst_buffer_unmap(b, &map);
                       ++px->frames;
                     }),
                     &px);
    gst_object_unref(out);
    gst_element_set_state(p, GST_STATE_PLAYING);
    GstBus* bus = gst_element_get_bus(p);
    GstMessage* m = gst_bus_timed_pop_filtered(
        bus, 20 * GST_SECOND, static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(GST_MESSAGE_TYPE(m), GST_MESSAGE_EOS);
    gst_message_unref(m);
    gst_object_unref(bus);
    gst_element_set_state(p, GST_STATE_NULL);
    gst_object_unref(p);
    ASSERT_GE(px.frames, 1);
    EXPECT_GT(px.centre[0], 200);  // the ball, white
    EXPECT_GT(px.centre[1], 200);
    if (alpha) {
      EXPECT_GT(px.corner[0], 200);  // red: the background shows through
      EXPECT_LT(px.corner[1], 60);
    } else {
      EXPECT_LT(px.corner[0], 60);  // projtrack's black frame covers it
    }
  }
}

}  // namespace
