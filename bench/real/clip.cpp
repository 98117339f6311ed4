#include "clip.hpp"

#include <gst/app/gstappsink.h>
#include <gst/check/gstharness.h>
#include <gst/video/video.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "element_harness.hpp"

namespace projtrack::bench {

Clip::~Clip() { release_frames(); }

void Clip::release_frames() {
  for (GstBuffer* b : i420_buffers) gst_buffer_unref(b);
  for (GstBuffer* b : rgb_buffers) gst_buffer_unref(b);
  i420_buffers = {};
  rgb_buffers = {};
  frames = {};
  median_.release();
}

const cv::Mat& Clip::median_luma() const {
  if (median_.empty() && !frames.empty()) {
    const std::size_t n = std::min<std::size_t>(99, frames.size());
    std::vector<cv::Mat> samples;
    for (std::size_t k = 0; k < n; ++k)
      samples.push_back(luma(static_cast<int>(k * frames.size() / n)));
    median_.create(height, width, CV_8UC1);
    std::vector<std::uint8_t> v(n);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        for (std::size_t k = 0; k < n; ++k) v[k] = samples[k].at<std::uint8_t>(y, x);
        std::nth_element(v.begin(), v.begin() + n / 2, v.end());
        median_.at<std::uint8_t>(y, x) = v[n / 2];
      }
  }
  return median_;
}

std::string Clip::caps(const char* format) const {
  return raw_caps(format, width, height, fps_n, fps_d);
}

namespace {

// The planes of a mapped I420 video frame, copied.
I420Frame copy_planes(GstVideoFrame& f) {
  I420Frame out;
  cv::Mat* planes[] = {&out.y, &out.u, &out.v};
  for (int p = 0; p < 3; ++p) {
    const cv::Mat view(GST_VIDEO_FRAME_COMP_HEIGHT(&f, p), GST_VIDEO_FRAME_COMP_WIDTH(&f, p),
                       CV_8UC1, GST_VIDEO_FRAME_PLANE_DATA(&f, p),
                       GST_VIDEO_FRAME_PLANE_STRIDE(&f, p));
    *planes[p] = view.clone();
  }
  return out;
}

// Appends the I420 frame in `buffer` (described by `caps`) to the clip.
void append(Clip& c, GstCaps* caps, GstBuffer* buffer, GstClockTime pts) {
  GstVideoInfo info;
  GstVideoFrame f;
  if (!gst_video_info_from_caps(&info, caps) ||
      !gst_video_frame_map(&f, &info, buffer, GST_MAP_READ))
    return;
  c.width = GST_VIDEO_INFO_WIDTH(&info);
  c.height = GST_VIDEO_INFO_HEIGHT(&info);
  if (GST_VIDEO_INFO_FPS_N(&info) > 0) {
    c.fps_n = GST_VIDEO_INFO_FPS_N(&info);
    c.fps_d = GST_VIDEO_INFO_FPS_D(&info);
  }
  c.frames.push_back(copy_planes(f));
  c.pts.push_back(pts);
  gst_video_frame_unmap(&f);
}

bool decode_file(const std::string& path, Clip& c, int max_frames) {
  gchar* quoted = g_strescape(path.c_str(), nullptr);
  const std::string launch = "filesrc location=\"" + std::string(quoted) +
                             "\" ! decodebin ! videoconvert ! video/x-raw,format=I420 ! "
                             "appsink name=sink sync=false";
  g_free(quoted);
  GError* err = nullptr;
  GstElement* p = gst_parse_launch(launch.c_str(), &err);
  if (!p) {
    std::fprintf(stderr, "projtrack-real: %s\n", err ? err->message : "cannot decode");
    g_clear_error(&err);
    return false;
  }
  GstElement* sink = gst_bin_get_by_name(GST_BIN(p), "sink");
  gst_element_set_state(p, GST_STATE_PLAYING);
  bool failed = false;
  while (max_frames <= 0 || static_cast<int>(c.frames.size()) < max_frames) {
    GstSample* s = gst_app_sink_try_pull_sample(GST_APP_SINK(sink), 10 * GST_SECOND);
    if (!s) {
      if (!gst_app_sink_is_eos(GST_APP_SINK(sink))) failed = true;  // an error, or stuck
      break;
    }
    GstBuffer* b = gst_sample_get_buffer(s);
    append(c, gst_sample_get_caps(s), b, GST_BUFFER_PTS(b));
    gst_sample_unref(s);
  }
  gst_element_set_state(p, GST_STATE_NULL);
  gst_object_unref(sink);
  gst_object_unref(p);
  if (failed) std::fprintf(stderr, "projtrack-real: %s: decoding stopped (no EOS)\n", path.c_str());
  return !failed && !c.frames.empty();
}

// Frames read with OpenCV (a pgm sequence's GRAY8 pixels, what pnmdec gives for 8-bit P5; or a
// file through OpenCV's FFmpeg reader, BGR), each pushed through videoconvert into I420 as an
// appsrc pipeline would, at the file's rate (30 frames a second for images).
bool decode_opencv(const std::string& path, bool images, Clip& c, int max_frames) {
  std::vector<cv::String> files;
  cv::VideoCapture cap;
  if (images) {
    cv::glob(path, files, false);
    std::sort(files.begin(), files.end());
  } else if (!cap.open(path)) {
    return false;
  }
  const double fps = images ? 30 : cap.get(cv::CAP_PROP_FPS);
  if (fps > 0) c.fps_n = static_cast<int>(std::lround(fps * 1000)), c.fps_d = 1000;
  GstHarness* h = nullptr;
  GstVideoInfo info;
  for (std::size_t k = 0;; ++k) {
    if (max_frames > 0 && static_cast<int>(c.frames.size()) >= max_frames) break;
    cv::Mat img;
    if (images && k < files.size()) img = cv::imread(files[k], cv::IMREAD_GRAYSCALE);
    if (!images) cap.read(img);
    if (img.empty()) break;
    const char* format = images ? "GRAY8" : "BGR";
    if (!h) {
      h = gst_harness_new("videoconvert");
      gst_harness_set_src_caps_str(h,
                                   raw_caps(format, img.cols, img.rows, c.fps_n, c.fps_d).c_str());
      gst_harness_set_sink_caps_str(h,
                                    raw_caps("I420", img.cols, img.rows, c.fps_n, c.fps_d).c_str());
      gst_video_info_set_format(&info, gst_video_format_from_string(format), img.cols, img.rows);
    }
    GstBuffer* b = gst_buffer_new_allocate(nullptr, GST_VIDEO_INFO_SIZE(&info), nullptr);
    GstMapInfo m;
    gst_buffer_map(b, &m, GST_MAP_WRITE);
    const std::size_t row = img.cols * img.elemSize();
    for (int y = 0; y < img.rows; ++y)
      std::memcpy(m.data + static_cast<std::size_t>(y) * GST_VIDEO_INFO_PLANE_STRIDE(&info, 0),
                  img.ptr(y), row);
    gst_buffer_unmap(b, &m);
    const GstClockTime pts = gst_util_uint64_scale(k, GST_SECOND * c.fps_d, c.fps_n);
    GST_BUFFER_PTS(b) = pts;
    GstBuffer* out = gst_harness_push_and_pull(h, b);
    if (!out) break;
    GstCaps* caps = gst_pad_get_current_caps(h->sinkpad);
    append(c, caps, out, pts);
    gst_caps_unref(caps);
    gst_buffer_unref(out);
  }
  if (h) gst_harness_teardown(h);
  return !c.frames.empty();
}

GstBuffer* rgb_buffer(const cv::Mat& bgr, GstClockTime pts, GstClockTime duration) {
  GstVideoInfo info;
  gst_video_info_set_format(&info, GST_VIDEO_FORMAT_RGB, bgr.cols, bgr.rows);
  GstBuffer* b = gst_buffer_new_allocate(nullptr, GST_VIDEO_INFO_SIZE(&info), nullptr);
  GstMapInfo m;
  gst_buffer_map(b, &m, GST_MAP_WRITE);
  const int stride = GST_VIDEO_INFO_PLANE_STRIDE(&info, 0);
  cv::Mat rgb(bgr.rows, bgr.cols, CV_8UC3, m.data, stride);
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  gst_buffer_unmap(b, &m);
  GST_BUFFER_PTS(b) = pts;
  GST_BUFFER_DURATION(b) = duration;
  return b;
}

}  // namespace

bool decode(const std::string& path, const std::string& kind, Clip& c, int max_frames) {
  if (kind == "pgm" || kind == "opencv") return decode_opencv(path, kind == "pgm", c, max_frames);
  return decode_file(path, c, max_frames);
}

GstBuffer* i420_buffer(const I420Frame& f, GstClockTime pts, GstClockTime duration) {
  GstVideoInfo info;
  gst_video_info_set_format(&info, GST_VIDEO_FORMAT_I420, f.y.cols, f.y.rows);
  GstBuffer* b = gst_buffer_new_allocate(nullptr, GST_VIDEO_INFO_SIZE(&info), nullptr);
  GstMapInfo m;
  gst_buffer_map(b, &m, GST_MAP_WRITE);
  const cv::Mat* planes[] = {&f.y, &f.u, &f.v};
  for (int p = 0; p < 3; ++p) {
    cv::Mat dst(planes[p]->rows, planes[p]->cols, CV_8UC1,
                m.data + GST_VIDEO_INFO_PLANE_OFFSET(&info, p),
                GST_VIDEO_INFO_PLANE_STRIDE(&info, p));
    planes[p]->copyTo(dst);
  }
  gst_buffer_unmap(b, &m);
  GST_BUFFER_PTS(b) = pts;
  GST_BUFFER_DURATION(b) = duration;
  return b;
}

cv::Mat to_bgr(const I420Frame& f) {
  const int w = f.y.cols, h = f.y.rows, we = (w + 1) & ~1, he = (h + 1) & ~1;
  cv::Mat packed(he * 3 / 2, we, CV_8UC1);
  cv::Mat y = packed.rowRange(0, he);
  cv::copyMakeBorder(f.y, y, 0, he - h, 0, we - w, cv::BORDER_REPLICATE);
  const std::size_t quarter = static_cast<std::size_t>(we / 2) * (he / 2);
  cv::Mat u(he / 2, we / 2, CV_8UC1, packed.data + static_cast<std::size_t>(we) * he);
  cv::Mat v(he / 2, we / 2, CV_8UC1, packed.data + static_cast<std::size_t>(we) * he + quarter);
  f.u.copyTo(u);
  f.v.copyTo(v);
  cv::Mat bgr;
  cv::cvtColor(packed, bgr, cv::COLOR_YUV2BGR_I420);
  return w == we && h == he ? bgr : bgr(cv::Rect(0, 0, w, h)).clone();
}

I420Frame from_bgr(const cv::Mat& bgr) {
  cv::Mat packed;
  cv::cvtColor(bgr, packed, cv::COLOR_BGR2YUV_I420);
  const int w = bgr.cols, h = bgr.rows;
  const std::size_t quarter = static_cast<std::size_t>(w / 2) * (h / 2);
  I420Frame f;
  f.y = packed.rowRange(0, h).clone();
  f.u = cv::Mat(h / 2, w / 2, CV_8UC1, packed.data + static_cast<std::size_t>(w) * h).clone();
  f.v = cv::Mat(h / 2, w / 2, CV_8UC1, packed.data + static_cast<std::size_t>(w) * h + quarter)
            .clone();
  return f;
}

void make_buffers(Clip& c) {
  const GstClockTime duration = gst_util_uint64_scale(GST_SECOND, c.fps_d, c.fps_n);
  for (std::size_t i = 0; i < c.frames.size(); ++i) {
    c.i420_buffers.push_back(i420_buffer(c.frames[i], c.pts[i], duration));
    c.rgb_buffers.push_back(rgb_buffer(to_bgr(c.frames[i]), c.pts[i], duration));
  }
}

}  // namespace projtrack::bench
