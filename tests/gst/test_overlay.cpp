// The overlay's text, read back from the drawn frame in every format the element accepts: what a
// person sees on the video is the status, why, x, y and depth, legibly (each glyph's pixels
// recognised as that glyph of the font).
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "font.hpp"
#include "overlay.hpp"

namespace {

using projtrack::Method;
using projtrack::TrackResult;
using projtrack::TrackStatus;
using projtrack::gst::draw_overlay;
using projtrack::gst::glyph;
using projtrack::gst::kGlyphHeight;
using projtrack::gst::kGlyphWidth;
using projtrack::gst::overlay_text;
using projtrack::gst::panel_lines;
using projtrack::gst::text_scale;

struct GstEnvironment : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
};
const auto* const kGstEnvironment = ::testing::AddGlobalTestEnvironment(new GstEnvironment);

constexpr const char* kFormats[] = {"GRAY8", "I420", "YV12", "NV12", "NV21", "Y42B", "Y444",
                                    "YUY2",  "UYVY", "BGRx", "RGBx", "xRGB", "xBGR", "BGRA",
                                    "RGBA",  "ARGB", "ABGR", "BGR",  "RGB",  "AYUV", "A420"};

std::string caps(const char* format, int w, int h) {
  return "video/x-raw,format=" + std::string(format) + ",width=" + std::to_string(w) +
         ",height=" + std::to_string(h) + ",framerate=30/1";
}

// `in` converted from one format to another by videoconvert.
GstBuffer* convert(GstBuffer* in, const char* from, const char* to, int w, int h) {
  GstHarness* c = gst_harness_new("videoconvert");
  gst_harness_set_src_caps_str(c, caps(from, w, h).c_str());
  gst_harness_set_sink_caps_str(c, caps(to, w, h).c_str());
  GstBuffer* out = gst_harness_push_and_pull(c, in);
  gst_harness_teardown(c);
  return out;
}

// A webcam-like picture: a bright gradient, so the text must stand on its darkened panel.
GstBuffer* picture(int w, int h) {
  GstBuffer* b = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h, nullptr);
  GstMapInfo map;
  gst_buffer_map(b, &map, GST_MAP_WRITE);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) map.data[y * w + x] = static_cast<guint8>(150 + (x + y) % 100);
  gst_buffer_unmap(b, &map);
  return b;
}

// The text lines on a GRAY8 frame, read glyph by glyph from the overlay's layout (each font pixel
// a scale × scale square, sampled at its centre), each line up to the first cell that is no glyph.
std::vector<std::string> read_text(GstBuffer* gray, int w, int h) {
  const int scale = text_scale(h), pad = 2 * scale;
  const int advance = (kGlyphWidth + 1) * scale, line_height = (kGlyphHeight + 1) * scale;
  GstMapInfo map;
  gst_buffer_map(gray, &map, GST_MAP_READ);
  const int stride = static_cast<int>(map.size) / h;
  const auto ink = [&](int x, int y) { return map.data[y * stride + x] > 100; };
  std::vector<std::string> lines;
  for (int top = pad; top + line_height <= h; top += line_height) {
    std::string line;
    for (int left = pad; left + advance <= w; left += advance) {
      projtrack::gst::Glyph seen{};
      for (int row = 0; row < kGlyphHeight; ++row)
        for (int col = 0; col < kGlyphWidth; ++col)
          seen[row] = static_cast<guint8>(
              seen[row] << 1 | ink(left + col * scale + scale / 2, top + row * scale + scale / 2));
      char c = 0;
      for (char k = ' '; k <= '~'; ++k)
        if (glyph(k) == seen) c = k;
      if (!c) break;  // the picture beyond the panel
      line += c;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.empty()) break;
    lines.push_back(line);
  }
  gst_buffer_unmap(gray, &map);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& l : lines) all += (all.empty() ? "" : " ") + l;
  return all;
}

TrackResult lost_result() {
  TrackResult r;
  r.status = TrackStatus::Lost;
  r.detail = "the estimate covers the frame (a leak)";
  r.features.status = projtrack::EstimateStatus::Ok;
  r.features.centroid = {300.4, 260.0};
  r.features.area = 4321;
  r.features.bbox = {260, 220, 80, 80};
  r.has_pose = true;
  r.pose = {-0.06, 0.08, 1.25};
  return r;
}

TEST(Overlay, TextSaysTheStatusWhyAndThePointer) {
  const std::vector<std::string> lost = overlay_text(lost_result(), Method::GapTolerantFilling);
  ASSERT_GE(lost.size(), 3u);
  EXPECT_EQ(lost[0], "LOST: the estimate covers the frame (a leak)");
  EXPECT_EQ(lost[1], "x -0.06  y +0.08  depth 1.25");
  EXPECT_EQ(lost[2], "last seen at 300, 260  area 4321 px");

  TrackResult searching;
  searching.status = TrackStatus::Searching;
  searching.detail = "nothing moves yet";
  const std::vector<std::string> s = overlay_text(searching, Method::PixelFilling);
  EXPECT_EQ(s.front(), "SEARCHING: nothing moves yet");
  EXPECT_EQ(s.back(), "method pixel-filling");
  EXPECT_EQ(s.size(), 2u);  // no pointer, no centroid while searching

  TrackResult tracking = lost_result();
  tracking.status = TrackStatus::Ok;
  tracking.detail.clear();
  tracking.gesture = projtrack::Gesture::Push;
  const std::vector<std::string> t = overlay_text(tracking, Method::GridFilling);
  EXPECT_EQ(t[0], "TRACKING");
  EXPECT_EQ(t[2], "centroid 300, 260  area 4321 px");
  EXPECT_EQ(t[3], "PUSH");
}

TEST(Overlay, EveryGlyphIsDistinct) {
  for (char a = ' '; a <= '~'; ++a)
    for (char b = ' '; b < a; ++b) EXPECT_NE(glyph(a), glyph(b)) << a << ' ' << b;
  EXPECT_EQ(glyph('\n'), glyph('?'));  // outside printable ASCII
}

TEST(Overlay, SignsOutsideAsciiAreDrawnByLookAlikes) {
  using projtrack::gst::drawable;
  EXPECT_EQ(drawable("the area shrank to 0.40\u00d7 of the last frame's"),
            "the area shrank to 0.40x of the last frame's");
  EXPECT_EQ(drawable("\u2264 5 px \u2013 \u00b5s"), "<= 5 px - us");
  EXPECT_EQ(drawable("caf\u00e9 \U0001F600!"), "caf? ?!");  // one '?' a character
  EXPECT_EQ(drawable(std::string("\xC3", 1)), "?");         // a cut sequence
  // Every character drawable() gives has a glyph of its own, not the '?' of unknown ones.
  for (char c : drawable("\u00d7\u2013\u2014\u2264\u2265\u00b7\u00b2\u00b5"))
    EXPECT_NE(glyph(c), glyph('?')) << c;
}

TEST(Overlay, TheTextReadsBackInEveryFormatAt640x480) {
  const int w = 640, h = 480;
  const TrackResult r = lost_result();
  const std::string expected = joined(overlay_text(r, Method::GapTolerantFilling));
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    GstBuffer* buf = convert(picture(w, h), "GRAY8", format, w, h);
    GstVideoInfo info;
    GstCaps* c = gst_caps_from_string(caps(format, w, h).c_str());
    ASSERT_TRUE(gst_video_info_from_caps(&info, c));
    gst_caps_unref(c);
    GstVideoFrame frame;
    ASSERT_TRUE(gst_video_frame_map(&frame, &info, buf, GST_MAP_READWRITE));
    draw_overlay(&frame, Method::GapTolerantFilling, r, projtrack::Trace{});
    gst_video_frame_unmap(&frame);
    GstBuffer* gray = convert(buf, format, "GRAY8", w, h);
    const std::vector<std::string> lines = read_text(gray, w, h);
    gst_buffer_unref(gray);
    EXPECT_GT(lines.size(), 1u);  // wrapped to the frame's width
    EXPECT_EQ(joined(lines), expected);
  }
}

TEST(Overlay, TextScalesWithTheFrame) {
  EXPECT_EQ(text_scale(120), 1);
  EXPECT_EQ(text_scale(480), 2);
  EXPECT_EQ(text_scale(1080), 4);
  const int w = 320, h = 240;
  TrackResult waiting;
  waiting.status = TrackStatus::NoInnerPoint;
  waiting.detail = "no inner point: set one, or click in the video";
  GstBuffer* buf = picture(w, h);
  GstVideoInfo info;
  gst_video_info_set_format(&info, GST_VIDEO_FORMAT_GRAY8, w, h);
  GstVideoFrame frame;
  ASSERT_TRUE(gst_video_frame_map(&frame, &info, buf, GST_MAP_READWRITE));
  draw_overlay(&frame, Method::RayCasting, waiting, projtrack::Trace{});
  gst_video_frame_unmap(&frame);
  EXPECT_EQ(joined(read_text(buf, w, h)), joined(overlay_text(waiting, Method::RayCasting)));
  gst_buffer_unref(buf);
}

// A frame of `w` × `h` GRAY8 pixels of `value`, mapped, drawn on with `flags`; how many pixels
// changed and their bounds.
struct Drawn {
  int changed = 0;
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};

Drawn draw(int w, int h, const TrackResult& r, const projtrack::Trace& trace, unsigned flags) {
  GstBuffer* buf = gst_buffer_new_allocate(nullptr, static_cast<gsize>(w) * h, nullptr);
  gst_buffer_memset(buf, 0, 100, static_cast<gsize>(w) * h);
  GstVideoInfo info;
  gst_video_info_set_format(&info, GST_VIDEO_FORMAT_GRAY8, w, h);
  GstVideoFrame frame;
  Drawn d;
  if (!gst_video_frame_map(&frame, &info, buf, GST_MAP_READWRITE)) return d;
  draw_overlay(&frame, Method::GridFilling, r, trace, flags);
  const auto* data = static_cast<const guint8*>(GST_VIDEO_FRAME_PLANE_DATA(&frame, 0));
  const int stride = GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (data[y * stride + x] != 100) {
        ++d.changed;
        d.x0 = std::min(d.x0, x), d.y0 = std::min(d.y0, y);
        d.x1 = std::max(d.x1, x), d.y1 = std::max(d.y1, y);
      }
  gst_video_frame_unmap(&frame);
  gst_buffer_unref(buf);
  return d;
}

// The text panel fits the frame: at most a quarter of its height (160×120 once lost 40 % of the
// picture to it), the status's first line always, cut with "..." when it does not fit.
TEST(Overlay, ThePanelTakesAtMostAQuarterOfTheFrame) {
  TrackResult r = lost_result();
  r.gesture = projtrack::Gesture::Push;
  r.detail =
      "the area passed 2.0x the last frame's: a leak, not filled; five refused frames in "
      "a row are tolerated, the sixth drops the track and acquisition starts again";
  for (auto [w, h] :
       {std::pair{160, 120}, std::pair{320, 240}, std::pair{640, 480}, std::pair{1920, 1080}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    const Drawn d = draw(w, h, r, projtrack::Trace{}, projtrack::gst::kDrawStatus);
    EXPECT_GT(d.changed, 0);
    EXPECT_EQ(d.x0, 0);
    EXPECT_EQ(d.y0, 0);
    EXPECT_LE(d.y1 + 1, h / 4) << "rows of the panel";
    EXPECT_LE(d.changed, w * h / 4);
    const projtrack::gst::PanelText text = panel_lines(r, Method::GridFilling, w, h);
    ASSERT_GE(text.status_lines, 1u);
    EXPECT_EQ(text.lines[0].rfind("LOST", 0), 0u) << text.lines[0];
  }
  // Small: the status cut short, then the push (what a person must not miss).
  const projtrack::gst::PanelText small = panel_lines(r, Method::GridFilling, 160, 120);
  ASSERT_EQ(small.lines.size(), 2u);
  EXPECT_EQ(small.lines[0].substr(small.lines[0].size() - 3), "...");
  EXPECT_EQ(small.lines[1], "PUSH");
  // A detail of a usual length at 1080p: everything, uncut.
  TrackResult usual = lost_result();
  usual.gesture = projtrack::Gesture::Push;
  const projtrack::gst::PanelText large = panel_lines(usual, Method::GridFilling, 1920, 1080);
  EXPECT_EQ(joined(large.lines), joined(overlay_text(usual, Method::GridFilling)));
}

// draw-flags: each part of the overlay alone draws where that part is, and nothing else.
TEST(Overlay, DrawFlagsChooseWhatIsDrawn) {
  using namespace projtrack::gst;
  TrackResult r = lost_result();
  r.status = TrackStatus::Ok;
  r.detail.clear();
  r.features.inner_point = {300, 260};
  projtrack::Trace trace;
  trace.outline = {{262, 260}, {338, 260}};
  trace.runs.push_back({{270, 250}, {330, 250}});
  const int w = 640, h = 480;
  EXPECT_EQ(draw(w, h, r, trace, 0).changed, 0);
  const Drawn box = draw(w, h, r, trace, kDrawBox);
  EXPECT_EQ(box.x0, 260);
  EXPECT_EQ(box.x1, 339);
  EXPECT_EQ(box.changed, 4 * 79);  // its outline only
  const Drawn outline = draw(w, h, r, trace, kDrawOutline);
  EXPECT_EQ(outline.changed, 2 * 4);  // two points, 2×2 at this scale
  const Drawn grid = draw(w, h, r, trace, kDrawGrid);
  EXPECT_EQ(grid.changed, 61);
  EXPECT_EQ(grid.y0, 250);
  const Drawn inner = draw(w, h, r, trace, kDrawInnerPoint);
  EXPECT_EQ(inner.changed, 5 * 5);
  EXPECT_EQ(inner.x0, 298);
  const Drawn centroid = draw(w, h, r, trace, kDrawCentroid);
  EXPECT_NEAR((centroid.x0 + centroid.x1) / 2.0, 300, 1);
  EXPECT_EQ(centroid.changed, 2 * 19 - 1);
  const Drawn status = draw(w, h, r, trace, kDrawStatus);
  EXPECT_LT(status.y1, h / 4);
  EXPECT_GT(status.changed, 0);
  const Drawn all = draw(w, h, r, trace, kDrawAll);
  EXPECT_GT(all.changed, status.changed + box.changed);
}

}  // namespace
