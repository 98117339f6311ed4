#include "render.hpp"

#include <gst/video/video.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "element_harness.hpp"

namespace projtrack::bench {
namespace {

// The fields of one CSV line, with "..." quoting ("" inside for a quote).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted && ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (ch == '"') {
      quoted = !quoted;
    } else if (ch == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += ch;
    }
  }
  return out;
}

void write_jpeg(const cv::Mat& bgr, const std::string& folder, int i) {
  char file[32];
  std::snprintf(file, sizeof file, "/%03d.jpg", i);
  cv::imwrite(folder + file, bgr, {cv::IMWRITE_JPEG_QUALITY, 90});
}

}  // namespace

std::vector<RenderRequest> read_render_requests(const std::string& path) {
  std::vector<RenderRequest> out;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    const std::vector<std::string> f = csv_fields(line);
    if (f.size() < 4) continue;
    RenderRequest r{f[0], f[1], f[2], {}};
    std::istringstream frames(f[3]);
    for (int i; frames >> i;) r.frames.insert(i);
    out.push_back(r);
  }
  return out;
}

void render(const Clip& c, const RenderRequest& r, const std::string& dir) {
  const std::string folder = dir + "/" + c.name + "/" + r.slug;
  std::filesystem::create_directories(folder);
  if (r.props.empty()) {
    for (int i : r.frames)
      if (i >= 0 && i < static_cast<int>(c.frames.size()))
        write_jpeg(to_bgr(c.frames[i]), folder, i);
    return;
  }
  ElementHarness h("projtrack draw=true " + r.props, c.caps("I420"), false);
  const int last = r.frames.empty() ? -1 : *r.frames.rbegin();
  for (int i = 0; i <= last && i < static_cast<int>(c.frames.size()); ++i) {
    GstBuffer* copy = gst_buffer_copy_deep(c.i420_buffers[i]);
    GstBuffer* out = h.push_pull(copy);
    gst_buffer_unref(copy);
    if (!out) continue;
    if (r.frames.count(i)) {
      GstVideoInfo info;
      gst_video_info_set_format(&info, GST_VIDEO_FORMAT_I420, c.width, c.height);
      GstVideoFrame f;
      if (gst_video_frame_map(&f, &info, out, GST_MAP_READ)) {
        I420Frame planes;
        cv::Mat* p[] = {&planes.y, &planes.u, &planes.v};
        for (int k = 0; k < 3; ++k)
          *p[k] = cv::Mat(GST_VIDEO_FRAME_COMP_HEIGHT(&f, k), GST_VIDEO_FRAME_COMP_WIDTH(&f, k),
                          CV_8UC1, GST_VIDEO_FRAME_PLANE_DATA(&f, k),
                          GST_VIDEO_FRAME_PLANE_STRIDE(&f, k))
                      .clone();
        write_jpeg(to_bgr(planes), folder, i);
        gst_video_frame_unmap(&f);
      }
    }
    gst_buffer_unref(out);
  }
}

}  // namespace projtrack::bench
