// The overlay's text panel as the element draws it (gst/hud.cpp: the 5×7 font through the
// Painter, straight into the frame's planes) against cv::putText on each plane: see cases.hpp.
#include <gst/video/video.h>

#include <opencv2/imgproc.hpp>

#include "cases.hpp"
#include "painter.hpp"

namespace projtrack::handwritten {
namespace {

const std::vector<std::string> kLines = {"TRACKING", "x 960  y 540  depth 0.42",
                                         "gap-tolerant-filling"};

void hud_text(const Frame& f, const Effort& e, std::FILE* out) {
  GstVideoInfo info;
  gst_video_info_set_format(&info, GST_VIDEO_FORMAT_I420, f.width, f.height);
  GstBuffer* buffer = gst_buffer_new_allocate(nullptr, info.size, nullptr);
  gst_buffer_fill(buffer, 0, f.i420.data, std::min<gsize>(info.size, f.i420.total()));
  GstVideoFrame frame;
  gst_video_frame_map(&frame, &info, buffer, GST_MAP_READWRITE);
  // The element's text size (hud.cpp text_scale) and line spacing.
  const int scale = std::clamp(f.height / 240, 1, 8);
  const int line = (gst::kGlyphHeight + 1) * scale;
  cv::Mat y(f.height, f.width, CV_8U, GST_VIDEO_FRAME_PLANE_DATA(&frame, 0),
            GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 0));
  cv::Mat u(f.height / 2, f.width / 2, CV_8U, GST_VIDEO_FRAME_PLANE_DATA(&frame, 1),
            GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 1));
  cv::Mat v(f.height / 2, f.width / 2, CV_8U, GST_VIDEO_FRAME_PLANE_DATA(&frame, 2),
            GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 2));
  Row r{"text panel lines (bitmap font, drawn into the frame's planes)",
        "gst/font.cpp + gst/painter.hpp Painter::text",
        "cv::putText HERSHEY_PLAIN on the Y, U and V planes", f.name + " I420, 3 lines", ""};
  const Duel d = duel(
      [&] {
        gst::Painter paint(&frame);
        for (std::size_t i = 0; i < kLines.size(); ++i)
          paint.text(2 * scale, 2 * scale + static_cast<int>(i) * line, scale, kLines[i],
                     {64, 255, 64});
      },
      [&] {
        for (std::size_t i = 0; i < kLines.size(); ++i) {
          const int top = 2 * scale + static_cast<int>(i + 1) * line;
          cv::putText(y, kLines[i], {2 * scale, top}, cv::FONT_HERSHEY_PLAIN, scale * 0.6, 200);
          cv::putText(u, kLines[i], {scale, top / 2}, cv::FONT_HERSHEY_PLAIN, scale * 0.3, 60);
          cv::putText(v, kLines[i], {scale, top / 2}, cv::FONT_HERSHEY_PLAIN, scale * 0.3, 60);
        }
      },
      e.rounds, e.calls);
  r.same = "not compared (other glyphs)";
  write_row(out, r, d);
  gst_video_frame_unmap(&frame);
  gst_buffer_unref(buffer);
}

}  // namespace

void text_duels(const std::vector<Frame>& frames, const Effort& e, std::FILE* out) {
  for (const Frame& f : frames) hud_text(f, e, out);
}

}  // namespace projtrack::handwritten
