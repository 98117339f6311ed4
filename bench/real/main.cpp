// projtrack-real: every tracker on real footage, side by side on the same decoded frames
// (./run bench --real; docs/real_footage.md). The clips are opencv-doc's: a hand turning a cup,
// a hand turning a printed box (both with ground truth from bench/real/truth/), and people walking
// (vtest.avi, no held object: only whether a static region is ever reported as the object).
//
//   projtrack-real --out DIR --truth DIR --clip NAME=FILE... [--frames N]
//
// Writes DIR/runs.csv (one row per clip, tracker and frame), DIR/speed.csv (the clips scaled to
// 1080p beside a frame copy), DIR/meta.json, and DIR/frames/<clip>/<tracker>/NNN.jpg: the
// element's own overlay (draw=true) for the contact sheets.
#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <gst/video/video.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "element_harness.hpp"
#include "machine.hpp"
#include "progress.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/method.hpp"

namespace projtrack::bench {
namespace {

using Clock = std::chrono::steady_clock;

// ---- The clips --------------------------------------------------------------------------------

struct TruthFrame {
  Point2d centroid;
  double area = 0;
  Rect box;
  Point2i inner;  // the silhouette's point farthest from its border
  double luma = 0;
};

struct Clip {
  std::string name;
  std::string variant;  // empty for the clip as decoded; else how it was changed (see variant())
  std::string path;     // the file it was decoded from
  int width = 0, height = 0, fps_n = 30, fps_d = 1;
  std::vector<cv::Mat> i420;  // packed planes, (height * 3 / 2) × width
  std::vector<GstClockTime> pts;
  std::vector<TruthFrame> truth;  // empty: no ground truth
  std::vector<GstBuffer*> i420_buffers, rgb_buffers;
  ~Clip() {
    for (GstBuffer* b : i420_buffers) gst_buffer_unref(b);
    for (GstBuffer* b : rgb_buffers) gst_buffer_unref(b);
  }
  cv::Mat luma(int i) const { return i420[i].rowRange(0, height); }
  // The scene's background, for the static-region judgement: the per-pixel median luma of up to
  // 99 frames spread over the clip (people walk through it; the lawn and the signs stay).
  const cv::Mat& median_luma() const {
    if (median_.empty() && !i420.empty()) {
      const std::size_t n = std::min<std::size_t>(99, i420.size());
      std::vector<cv::Mat> samples;
      for (std::size_t k = 0; k < n; ++k)
        samples.push_back(luma(static_cast<int>(k * i420.size() / n)));
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
  mutable cv::Mat median_;
  std::string caps(const char* format) const {
    return raw_caps(format, width, height, fps_n, fps_d);
  }
};

GstBuffer* buffer_of(const cv::Mat& packed, GstClockTime pts, GstClockTime duration) {
  const gsize n = packed.total() * packed.elemSize();
  GstBuffer* b = gst_buffer_new_allocate(nullptr, n, nullptr);
  gst_buffer_fill(b, 0, packed.data, n);
  GST_BUFFER_PTS(b) = pts;
  GST_BUFFER_DURATION(b) = duration;
  return b;
}

// Decodes `path` as a user's pipeline would (filesrc ! decodebin ! videoconvert), into I420.
bool decode(const std::string& path, Clip& c, int max_frames) {
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
  while (max_frames <= 0 || static_cast<int>(c.i420.size()) < max_frames) {
    GstSample* s = gst_app_sink_pull_sample(GST_APP_SINK(sink));
    if (!s) break;
    GstVideoInfo info;
    GstVideoFrame f;
    if (gst_video_info_from_caps(&info, gst_sample_get_caps(s)) &&
        gst_video_frame_map(&f, &info, gst_sample_get_buffer(s), GST_MAP_READ)) {
      c.width = GST_VIDEO_INFO_WIDTH(&info);
      c.height = GST_VIDEO_INFO_HEIGHT(&info);
      if (GST_VIDEO_INFO_FPS_N(&info) > 0) {
        c.fps_n = GST_VIDEO_INFO_FPS_N(&info);
        c.fps_d = GST_VIDEO_INFO_FPS_D(&info);
      }
      cv::Mat packed(c.height * 3 / 2, c.width, CV_8UC1);
      std::uint8_t* dst = packed.data;
      for (int plane = 0; plane < 3; ++plane) {
        const int w = GST_VIDEO_FRAME_COMP_WIDTH(&f, plane);
        const int h = GST_VIDEO_FRAME_COMP_HEIGHT(&f, plane);
        const auto* src = static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(&f, plane));
        for (int y = 0; y < h; ++y, dst += w)
          std::memcpy(
              dst, src + static_cast<std::ptrdiff_t>(y) * GST_VIDEO_FRAME_PLANE_STRIDE(&f, plane),
              w);
      }
      c.i420.push_back(packed);
      c.pts.push_back(GST_BUFFER_PTS(gst_sample_get_buffer(s)));
      gst_video_frame_unmap(&f);
    }
    gst_sample_unref(s);
  }
  gst_element_set_state(p, GST_STATE_NULL);
  gst_object_unref(sink);
  gst_object_unref(p);
  return !c.i420.empty();
}

// bench/real/truth/<clip>.csv, written by bench/real/label_truth.py.
std::vector<TruthFrame> read_truth(const std::string& path) {
  std::vector<TruthFrame> t;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    int frame;
    TruthFrame f;
    s >> frame >> f.centroid.x >> f.centroid.y >> f.area >> f.box.x >> f.box.y >> f.box.width >>
        f.box.height >> f.inner.x >> f.inner.y >> f.luma;
    if (!s || frame != static_cast<int>(t.size())) return {};
    t.push_back(f);
  }
  return t;
}

// Whether the clip's frames are those the truth was labelled on: their mean luma follows the
// truth's through one affine map (limited or full range) to within 1.5 levels on every frame.
bool same_frames(const Clip& c) {
  const std::size_t n = c.i420.size();
  std::vector<double> x(n), y(n);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = c.truth[i].luma;
    y[i] = cv::mean(c.luma(static_cast<int>(i)))[0];
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  // A flat clip (or one frame) fixes no slope: take the limited-range map's.
  const double slope = sxx > 1e-6 ? sxy / sxx : 219.0 / 255.0;
  if (slope < 0.7 || slope > 1.3) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(my + slope * (x[i] - mx) - y[i]) > 1.5) return false;
  return true;
}

// Fills the buffers each tracker is given (I420 for projtrack, RGB for cvtracker).
void make_buffers(Clip& c) {
  const GstClockTime duration = gst_util_uint64_scale(GST_SECOND, c.fps_d, c.fps_n);
  cv::Mat rgb;
  for (std::size_t i = 0; i < c.i420.size(); ++i) {
    c.i420_buffers.push_back(buffer_of(c.i420[i], c.pts[i], duration));
    cv::cvtColor(c.i420[i], rgb, cv::COLOR_YUV2RGB_I420);
    c.rgb_buffers.push_back(buffer_of(rgb, c.pts[i], duration));
  }
}

// The planes of a packed I420 frame, as 2-D views.
struct Planes {
  cv::Mat y, u, v;
  Planes(cv::Mat& i420, int w, int h)
      : y(h, w, CV_8UC1, i420.data),
        u(h / 2, w / 2, CV_8UC1, i420.data + static_cast<std::size_t>(w) * h),
        v(h / 2, w / 2, CV_8UC1, i420.data + static_cast<std::size_t>(w) * h + (w / 2) * (h / 2)) {}
};

// The clip as footage we never tuned on would show it: other light, noise, mirrored, faster.
// Their settings are written to meta.json (write_meta), from which the report describes them.
//   mirror  left and right swapped (the truth too)
//   dark    a dimmer scene: luma at kDarkLuma of its range above black, chroma at kDarkChroma
//           of its swing
//   warm    a warm light: luma × kWarmLuma, Cb shifted by kWarmCb, Cr by kWarmCr
//   dim     a dim room: the light at kDimLight (luma and chroma's distance from neutral × it)
//   bright  overexposed: luma × kBrightGain + kBrightOffset, the highlights burnt out at 255
//   gamma   shadows lifted: luma through a gamma of kGamma (255 · (Y / 255)^kGamma)
//   noise   sensor noise: Gaussian, σ kNoiseLuma grey levels on luma, kNoiseChroma on chroma
//           (fixed seed)
//   fast    every kFastStep-th frame: kFastStep times the motion between frames
constexpr double kDarkLuma = 0.55, kDarkChroma = 0.8;
constexpr double kDimLight = 0.4;
constexpr double kWarmLuma = 0.92, kWarmCb = -10, kWarmCr = 12;
constexpr double kBrightGain = 1.35, kBrightOffset = -20;
constexpr double kGamma = 0.5;
constexpr double kNoiseLuma = 8, kNoiseChroma = 4;
constexpr int kFastStep = 3;
constexpr const char* kVariants[] = {"mirror", "dark", "dim",   "bright",
                                     "gamma",  "warm", "noise", "fast"};

std::unique_ptr<Clip> variant(const Clip& base, const std::string& how) {
  auto c = std::make_unique<Clip>();
  c->name = base.name + "-" + how;
  c->variant = how;
  c->path = base.path;
  c->width = base.width;
  c->height = base.height;
  c->fps_n = base.fps_n;
  c->fps_d = base.fps_d;
  const int w = base.width, h = base.height;
  cv::RNG rng(12345);
  for (std::size_t i = 0; i < base.i420.size(); ++i) {
    if (how == "fast" && i % kFastStep) continue;
    cv::Mat f = base.i420[i].clone();
    Planes p(f, w, h);
    if (how == "mirror") {
      for (cv::Mat* m : {&p.y, &p.u, &p.v}) {
        cv::Mat flipped;
        cv::flip(*m, flipped, 1);
        flipped.copyTo(*m);
      }
    } else if (how == "dark") {
      p.y.convertTo(p.y, -1, kDarkLuma, 16 * (1 - kDarkLuma));
      p.u.convertTo(p.u, -1, kDarkChroma, 128 * (1 - kDarkChroma));
      p.v.convertTo(p.v, -1, kDarkChroma, 128 * (1 - kDarkChroma));
    } else if (how == "dim") {
      p.y.convertTo(p.y, -1, kDimLight, 0);
      p.u.convertTo(p.u, -1, kDimLight, 128 * (1 - kDimLight));
      p.v.convertTo(p.v, -1, kDimLight, 128 * (1 - kDimLight));
    } else if (how == "bright") {
      p.y.convertTo(p.y, -1, kBrightGain, kBrightOffset);  // saturates at 0 and 255
    } else if (how == "gamma") {
      cv::Mat lut(1, 256, CV_8U);
      for (int v = 0; v < 256; ++v)
        lut.at<std::uint8_t>(v) =
            cv::saturate_cast<std::uint8_t>(255 * std::pow(v / 255.0, kGamma));
      cv::LUT(p.y, lut, p.y);
    } else if (how == "warm") {
      p.y.convertTo(p.y, -1, kWarmLuma, 0);
      p.u.convertTo(p.u, -1, 1, kWarmCb);
      p.v.convertTo(p.v, -1, 1, kWarmCr);
    } else if (how == "noise") {
      for (auto [m, sigma] :
           {std::pair{&p.y, kNoiseLuma}, {&p.u, kNoiseChroma}, {&p.v, kNoiseChroma}}) {
        cv::Mat n(m->size(), CV_16SC1), wide;
        rng.fill(n, cv::RNG::NORMAL, 0, sigma);
        m->convertTo(wide, CV_16SC1);
        wide += n;
        wide.convertTo(*m, CV_8UC1);
      }
    }
    c->i420.push_back(f);
    c->pts.push_back(base.pts[i]);
    if (base.truth.empty()) continue;
    TruthFrame t = base.truth[i];
    if (how == "mirror") {
      t.centroid.x = w - 1 - t.centroid.x;
      t.box.x = w - t.box.x - t.box.width;
      t.inner.x = w - 1 - t.inner.x;
    }
    c->truth.push_back(t);
  }
  make_buffers(*c);
  return c;
}

// A variant's truth, in the layout of bench/real/truth/<clip>.csv, for the report.
void write_truth(const Clip& c, const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::FILE* f = std::fopen((dir + "/" + c.name + ".csv").c_str(), "w");
  if (!f) return;
  std::fprintf(f, "frame,centroid_x,centroid_y,area,x,y,width,height,inner_x,inner_y,luma_mean\n");
  for (std::size_t i = 0; i < c.truth.size(); ++i) {
    const TruthFrame& t = c.truth[i];
    std::fprintf(f, "%zu,%.2f,%.2f,%.0f,%d,%d,%d,%d,%d,%d,%.2f\n", i, t.centroid.x, t.centroid.y,
                 t.area, t.box.x, t.box.y, t.box.width, t.box.height, t.inner.x, t.inner.y,
                 cv::mean(c.luma(static_cast<int>(i)))[0]);
  }
  std::fclose(f);
}

// ---- What a tracker reports on one frame -------------------------------------------------------

struct Report {
  std::string status = "none";  // projtrack's status; "ok" / "lost" for the box trackers
  bool has_features = false;    // a centroid, an area and a box measured on this frame
  Point2d centroid;
  double area = 0;
  Rect box;
  bool has_pose = false;
  double position_x = 0, position_y = 0, depth = 0;
  bool push = false, acquired = false;
  double us = 0;  // time to process the frame
  std::string detail;
};

double field_double(const GstStructure* s, const char* name) {
  double v = 0;
  gst_structure_get_double(s, name, &v);
  return v;
}

int field_int(const GstStructure* s, const char* name) {
  int v = 0;
  gst_structure_get_int(s, name, &v);
  return v;
}

bool is_tracking_status(const std::string& s) {
  return s == "ok" || s == "reached-border" || s == "covers-frame";
}

// The element's message about this frame.
void read_projtrack_message(const GstStructure* s, Report& r) {
  r.status = gst_structure_get_string(s, "status");
  // A lost track's message holds the last accepted features: not a measurement of this frame.
  r.has_features = is_tracking_status(r.status) && gst_structure_has_field(s, "area");
  if (gst_structure_has_field(s, "area")) {
    r.centroid = {field_double(s, "centroid-x"), field_double(s, "centroid-y")};
    r.area = field_double(s, "area");
    r.box = {field_int(s, "x"), field_int(s, "y"), field_int(s, "width"), field_int(s, "height")};
  }
  if (gst_structure_has_field(s, "depth")) {
    r.has_pose = true;
    r.position_x = field_double(s, "position-x");
    r.position_y = field_double(s, "position-y");
    r.depth = field_double(s, "depth");
  }
  const char* g = gst_structure_get_string(s, "gesture");
  r.push = g && std::strcmp(g, "push") == 0;
  gboolean acquired = FALSE;
  r.acquired = gst_structure_get_boolean(s, "acquired", &acquired) && acquired;
  if (const char* d = gst_structure_get_string(s, "detail")) r.detail = d;
}

double micros_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

// One tracker over one clip, frame after frame.
struct Tracker {
  std::string name;
  std::function<Report(int)> process;
};

// The element's properties in every run, per clip, for meta.json: what the report says was run.
std::map<std::string, std::map<std::string, std::string>> run_properties;

Tracker projtrack_tracker(const Clip& c, const std::string& name, const std::string& props) {
  run_properties[c.name][name] = props;
  auto h = std::make_shared<ElementHarness>("projtrack " + props, c.caps("I420"), true);
  return {name, [h, &c](int i) {
            Report r;
            const auto t0 = Clock::now();
            GstBuffer* out = h->push_pull(c.i420_buffers[i]);
            r.us = micros_since(t0);
            if (out) gst_buffer_unref(out);
            for (GstMessage* m : h->take_messages()) {
              const GstStructure* s = gst_message_get_structure(m);
              if (gst_structure_has_name(s, "projtrack")) read_projtrack_message(s, r);
              gst_message_unref(m);
            }
            return r;
          }};
}

// gst-plugins-bad's cvtracker: started from the first frame's true box; its ROI meta is the box.
// On the first frame it only starts (no meta): that frame reports the box it was given.
Tracker cvtracker_tracker(const Clip& c, const std::string& algorithm) {
  const Rect& b = c.truth[0].box;
  const std::string launch = "cvtracker algorithm=" + algorithm +
                             " draw-rect=false object-initial-x=" + std::to_string(b.x) +
                             " object-initial-y=" + std::to_string(b.y) +
                             " object-initial-width=" + std::to_string(b.width) +
                             " object-initial-height=" + std::to_string(b.height);
  run_properties[c.name]["cvtracker " + algorithm] = launch;
  auto h = std::make_shared<ElementHarness>(launch, c.caps("RGB"), false);
  return {"cvtracker " + algorithm, [h, &c, b](int i) {
            Report r;
            const auto t0 = Clock::now();
            GstBuffer* out = h->push_pull(c.rgb_buffers[i]);
            r.us = micros_since(t0);
            std::optional<Rect> box;
            if (i == 0) box = b;
            if (out) {
              gpointer state = nullptr;
              while (GstMeta* m = gst_buffer_iterate_meta_filtered(
                         out, &state, GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE)) {
                const auto* roi = reinterpret_cast<GstVideoRegionOfInterestMeta*>(m);
                // Its box is kept as unsigned: a box partly left of or above the frame wraps.
                box = Rect{static_cast<int>(roi->x), static_cast<int>(roi->y),
                           static_cast<int>(roi->w), static_cast<int>(roi->h)};
              }
              gst_buffer_unref(out);
            }
            if (box) {
              r.status = "ok";
              r.has_features = true;
              r.box = *box;
              r.centroid = {box->x + (box->width - 1) / 2.0, box->y + (box->height - 1) / 2.0};
              r.area = static_cast<double>(box->width) * box->height;
            } else {
              r.status = "lost";
            }
            return r;
          }};
}

// OpenCV's CamShift on the back projection of a 2-D hue–saturation histogram of the first
// frame's true box, as issue 12 asks (OpenCV's camshiftdemo uses a hue-only histogram; hue and
// saturation together also tell a grey object from a white one). Pixels outside camshiftdemo's
// mask (saturation below kCamShiftSatMin or value below kCamShiftValMin) count neither in the
// histogram nor in the back projection. CamShift runs from the last window, and a collapsed
// window restarts around its centre as in the demo. Given BGR frames, it converts them to HSV
// itself (timed).
constexpr int kCamShiftHueBins = 30, kCamShiftSatBins = 32;
constexpr int kCamShiftSatMin = 30, kCamShiftValMin = 10;

Tracker camshift_tracker(const Clip& c) {
  struct State {
    cv::Mat hist, bgr, hsv, mask, backproj;
    cv::Rect window;
  };
  auto st = std::make_shared<State>();
  return {"CamShift", [st, &c](int i) {
            Report r;
            cv::cvtColor(c.i420[i], st->bgr, cv::COLOR_YUV2BGR_I420);  // not timed: the input
            const auto t0 = Clock::now();
            const float hranges[] = {0, 180}, sranges[] = {0, 256};
            const float* ranges[] = {hranges, sranges};
            const int sizes[] = {kCamShiftHueBins, kCamShiftSatBins}, channels[] = {0, 1};
            cv::cvtColor(st->bgr, st->hsv, cv::COLOR_BGR2HSV);
            cv::inRange(st->hsv, cv::Scalar(0, kCamShiftSatMin, kCamShiftValMin),
                        cv::Scalar(180, 256, 256), st->mask);
            if (i == 0) {
              const Rect& b = c.truth[0].box;
              st->window = cv::Rect(b.x, b.y, b.width, b.height) &
                           cv::Rect(0, 0, st->hsv.cols, st->hsv.rows);
              cv::Mat roi(st->hsv, st->window), maskroi(st->mask, st->window);
              cv::calcHist(&roi, 1, channels, maskroi, st->hist, 2, sizes, ranges);
              cv::normalize(st->hist, st->hist, 0, 255, cv::NORM_MINMAX);
            }
            cv::calcBackProject(&st->hsv, 1, channels, st->hist, st->backproj, ranges);
            st->backproj &= st->mask;
            cv::RotatedRect rr;
            if (st->window.area() > 0)
              rr = cv::CamShift(
                  st->backproj, st->window,
                  cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 10, 1));
            r.us = micros_since(t0);
            if (st->window.area() <= 1) {  // the demo's recovery: a window around the centre
              const int cols = st->backproj.cols, rows = st->backproj.rows;
              const int rr_ = (std::min(cols, rows) + 5) / 6;
              st->window = cv::Rect(st->window.x - rr_, st->window.y - rr_, 2 * rr_, 2 * rr_) &
                           cv::Rect(0, 0, cols, rows);
              r.status = "lost";
              return r;
            }
            r.status = "ok";
            r.has_features = true;
            const cv::Rect b = rr.boundingRect() & cv::Rect(0, 0, c.width, c.height);
            r.box = {b.x, b.y, b.width, b.height};
            r.centroid = {rr.center.x, rr.center.y};
            r.area = static_cast<double>(rr.size.width) * rr.size.height;
            return r;
          }};
}

// ---- Output -------------------------------------------------------------------------------------

std::FILE* runs_csv = nullptr;
std::FILE* speed_csv = nullptr;

// A pixel has changed when its luma differs by more than this many grey levels (written to
// meta.json for the report).
constexpr int kChangedLevels = 20;

// The share of the box's pixels whose luma changed by more than kChangedLevels in the last two
// frames: a walking person's box has many, a static region of the background almost none.
double moving_share(const Clip& c, int i, const Rect& box) {
  if (i < 2) return -1;  // not known yet
  const cv::Rect r =
      cv::Rect(box.x, box.y, box.width, box.height) & cv::Rect(0, 0, c.width, c.height);
  if (r.area() <= 0) return 0;
  cv::Mat diff;
  cv::absdiff(c.luma(i)(r), c.luma(i - 2)(r), diff);
  return static_cast<double>(cv::countNonZero(diff > kChangedLevels)) / r.area();
}

// The share of `box`'s pixels on frame `i` that differ from the clip's median frame by more than
// kChangedLevels grey levels: near 0 on a piece of the scene's background (a sign, the lawn), high
// on what passes through it.
double scene_share(const Clip& c, int i, const Rect& box) {
  const cv::Rect r =
      cv::Rect(box.x, box.y, box.width, box.height) & cv::Rect(0, 0, c.width, c.height);
  if (r.area() <= 0) return 0;
  cv::Mat diff;
  cv::absdiff(c.luma(i)(r), c.median_luma()(r), diff);
  return static_cast<double>(cv::countNonZero(diff > kChangedLevels)) / r.area();
}

std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

void write_row(const Clip& c, const std::string& tracker, const std::string& group, int i,
               const Report& r) {
  std::fprintf(
      runs_csv,
      "%s,%s,%s,%d,%s,%d,%.3f,%.3f,%.1f,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,%d,%d,%.1f,%.4f,%.4f,%s\n",
      c.name.c_str(), csv_text(tracker).c_str(), group.c_str(), i, r.status.c_str(), r.has_features,
      r.centroid.x, r.centroid.y, r.area, r.box.x, r.box.y, r.box.width, r.box.height, r.has_pose,
      r.position_x, r.position_y, r.depth, r.push, r.acquired, r.us,
      r.has_features ? moving_share(c, i, r.box) : -1.0,
      r.has_features ? scene_share(c, i, r.box) : -1.0, csv_text(r.detail).c_str());
}

constexpr const char* kNoSeedProps = "acquisition=auto";

std::string seed_props(const Clip& c) {
  const Point2i p = c.truth[0].inner;
  return "inner-point-x=" + std::to_string(p.x) + " inner-point-y=" + std::to_string(p.y);
}

// Every tracker over the clip, frame by frame, their order rotated on every frame so a noisy
// machine slows all of them alike.
// The nick of the element's default method, read from its property.
std::string default_method() {
  GstElement* e = gst_element_factory_make("projtrack", nullptr);
  GParamSpec* spec = g_object_class_find_property(G_OBJECT_GET_CLASS(e), "method");
  const GValue* def = g_param_spec_get_default_value(spec);
  const GEnumValue* v =
      g_enum_get_value(G_PARAM_SPEC_ENUM(spec)->enum_class, g_value_get_enum(def));
  std::string nick = v ? v->value_nick : "";
  gst_object_unref(e);
  return nick;
}

bool only_default = false;  // --only-default: the element's default method and no seed alone
// --seeds FILE: other points to seed the default method at, per clip (bench/real/seeds.py).
std::map<std::string, std::vector<Point2i>> other_seeds;

void run_all(const Clip& c, Progress& progress) {
  std::vector<std::pair<Tracker, std::string>> ts;  // tracker, group
  const bool reduced = only_default || !c.variant.empty();
  if (!c.truth.empty()) {
    for (Method m : kAllMethods) {
      if (reduced && method_name(m) != default_method()) continue;
      const std::string method(method_name(m));
      ts.push_back(
          {projtrack_tracker(c, "projtrack " + method, "method=" + method + " " + seed_props(c)),
           "projtrack seeded"});
    }
  }
  if (!c.truth.empty() && c.variant.empty() && other_seeds.count(c.name)) {
    for (const Point2i& p : other_seeds.at(c.name)) {
      const std::string at = std::to_string(p.x) + "," + std::to_string(p.y);
      ts.push_back({projtrack_tracker(c, "projtrack seeded at " + at,
                                      "inner-point-x=" + std::to_string(p.x) +
                                          " inner-point-y=" + std::to_string(p.y)),
                    "projtrack seeded elsewhere"});
    }
  }
  // No seed: the element finds the object itself. Said explicitly, not left to the default.
  ts.push_back({projtrack_tracker(c, "projtrack no seed", kNoSeedProps), "projtrack no seed"});
  if (!c.truth.empty() && !c.variant.empty()) {
    if (GstElementFactory* f = gst_element_factory_find("cvtracker")) {
      gst_object_unref(f);
      ts.push_back({cvtracker_tracker(c, "MOSSE"), "box tracker"});
    }
  }
  if (!c.truth.empty() && !reduced) {
    if (GstElementFactory* f = gst_element_factory_find("cvtracker")) {
      gst_object_unref(f);
      for (const char* a : {"MOSSE", "KCF", "CSRT", "MedianFlow"})
        ts.push_back({cvtracker_tracker(c, a), "box tracker"});
    } else {
      std::fprintf(stderr, "projtrack-real: cvtracker not found (gstreamer1.0-opencv)\n");
    }
    ts.push_back({camshift_tracker(c), "box tracker"});
  }
  const int n = static_cast<int>(c.i420.size());
  for (int i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < ts.size(); ++k) {
      auto& [t, group] = ts[(k + i) % ts.size()];
      write_row(c, t.name, group, i, t.process(i));
    }
    progress.advance(c.name + " frame " + std::to_string(i));
  }
}

// The element's own overlay on every frame (draw=true), for the contact sheets.
void draw_frames(const Clip& c, const std::string& dir, const std::string& name,
                 const std::string& props, Progress& progress) {
  const std::string folder = dir + "/" + c.name + "/" + name;
  std::filesystem::create_directories(folder);
  ElementHarness h("projtrack draw=true " + props, c.caps("I420"), false);
  cv::Mat bgr;
  for (std::size_t i = 0; i < c.i420.size(); ++i) {
    GstBuffer* copy = gst_buffer_copy_deep(c.i420_buffers[i]);
    GstBuffer* out = h.push_pull(copy);
    gst_buffer_unref(copy);
    if (out) {
      GstMapInfo map;
      if (gst_buffer_map(out, &map, GST_MAP_READ)) {
        const cv::Mat packed(c.height * 3 / 2, c.width, CV_8UC1, map.data);
        cv::cvtColor(packed, bgr, cv::COLOR_YUV2BGR_I420);
        char file[64];
        std::snprintf(file, sizeof file, "/%03zu.jpg", i);
        cv::imwrite(folder + file, bgr, {cv::IMWRITE_JPEG_QUALITY, 90});
        gst_buffer_unmap(out, &map);
      }
      gst_buffer_unref(out);
    }
    progress.advance(c.name + " overlay " + name);
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The clip scaled to 1920×1080: the element (seeded, default method) beside a copy of the frame
// and the harness alone, frame by frame in turn.
void speed_1080p(const Clip& c, Progress& progress) {
  const int w = 1920, h = 1080;
  const double sx = static_cast<double>(w) / c.width, sy = static_cast<double>(h) / c.height;
  const Point2i p = c.truth[0].inner;
  const std::string seed = "inner-point-x=" + std::to_string(static_cast<int>(p.x * sx)) +
                           " inner-point-y=" + std::to_string(static_cast<int>(p.y * sy));
  const std::string caps = raw_caps("I420", w, h, c.fps_n, c.fps_d);
  ElementHarness element("projtrack " + seed, caps, false), identity("identity", caps, false);
  std::vector<double> t_copy, t_element, t_identity;
  std::vector<std::uint8_t> copy_target(static_cast<std::size_t>(w) * h * 3 / 2);
  cv::Mat bgr, big, i420;
  for (std::size_t i = 0; i < c.i420.size(); ++i) {
    cv::cvtColor(c.i420[i], bgr, cv::COLOR_YUV2BGR_I420);
    cv::resize(bgr, big, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
    cv::cvtColor(big, i420, cv::COLOR_BGR2YUV_I420);
    GstBuffer* b = buffer_of(i420, c.pts[i], GST_CLOCK_TIME_NONE);
    for (int k = 0; k < 3; ++k) {
      const auto t0 = Clock::now();
      switch ((k + static_cast<int>(i)) % 3) {
        case 0: {
          GstMapInfo m;
          gst_buffer_map(b, &m, GST_MAP_READ);
          std::memcpy(copy_target.data(), m.data, std::min(m.size, copy_target.size()));
          gst_buffer_unmap(b, &m);
          t_copy.push_back(micros_since(t0));
          break;
        }
        case 1:
          element.run(b);
          t_element.push_back(micros_since(t0));
          break;
        default:
          identity.run(b);
          t_identity.push_back(micros_since(t0));
      }
    }
    gst_buffer_unref(b);
    progress.advance(c.name + " 1080p");
  }
  const auto row = [&](const char* what, const std::vector<double>& t) {
    std::fprintf(speed_csv, "%s,1920x1080,%s,%.2f,%zu\n", c.name.c_str(), what, median(t),
                 t.size());
  };
  row("frame copy", t_copy);
  row("projtrack", t_element);
  row("harness alone (identity)", t_identity);
}

// A JSON string literal.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", ch);
      out += esc;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

void write_meta(const std::string& dir, const std::vector<std::unique_ptr<Clip>>& clips) {
  std::ofstream meta(dir + "/meta.json");
  meta << "{\n  \"measured\": \"" << utc_now() << "\",\n  \"cpu\": \"" << cpu_model()
       << "\",\n  \"cores\": " << std::thread::hardware_concurrency() << ",\n  \"opencv\": \""
       << CV_VERSION << "\",\n  \"gstreamer\": \"" << gst_version_string()
       << "\",\n  \"default_method\": \"" << default_method() << "\",\n  \"methods\": [";
  bool first = true;
  for (const MethodInfo& m : kMethods) {
    meta << (first ? "" : ",") << "\n    {\"name\": " << json_string(std::string(m.nick))
         << ", \"family\": \"" << (m.family == Family::Rays ? "rays" : "fill")
         << "\", \"from_paper\": " << (m.from_paper ? "true" : "false") << "}";
    first = false;
  }
  meta << "\n  ],\n  \"camshift\": {\"histogram\": \"hue-saturation\", \"hue_bins\": "
       << kCamShiftHueBins << ", \"saturation_bins\": " << kCamShiftSatBins
       << ", \"saturation_min\": " << kCamShiftSatMin << ", \"value_min\": " << kCamShiftValMin
       << "},\n  \"variants\": {\"mirror\": {}, \"dark\": {\"luma\": " << kDarkLuma
       << ", \"chroma\": " << kDarkChroma << "}, \"dim\": {\"light\": " << kDimLight
       << "}, \"bright\": {\"gain\": " << kBrightGain << ", \"offset\": " << kBrightOffset
       << "}, \"gamma\": {\"gamma\": " << kGamma << "}, \"warm\": {\"luma\": " << kWarmLuma
       << ", \"cb\": " << kWarmCb << ", \"cr\": " << kWarmCr
       << "}, \"noise\": {\"luma_sigma\": " << kNoiseLuma << ", \"chroma_sigma\": " << kNoiseChroma
       << "}, \"fast\": {\"step\": " << kFastStep << "}},\n  \"changed_levels\": " << kChangedLevels
       << ",\n  \"clips\": {";
  for (std::size_t k = 0; k < clips.size(); ++k) {
    const Clip& c = *clips[k];
    meta << (k ? "," : "") << "\n    " << json_string(c.name) << ": {\"frames\": " << c.i420.size()
         << ", \"width\": " << c.width << ", \"height\": " << c.height
         << ", \"fps\": " << static_cast<double>(c.fps_n) / c.fps_d
         << ", \"truth\": " << (c.truth.empty() ? "false" : "true") << ", \"variant\": \""
         << c.variant << "\", \"path\": " << json_string(c.path) << ", \"properties\": {";
    bool first_run = true;
    if (run_properties.count(c.name))
      for (const auto& [name, props] : run_properties.at(c.name)) {
        meta << (first_run ? "" : ", ") << json_string(name) << ": " << json_string(props);
        first_run = false;
      }
    meta << "}}";
  }
  meta << "\n  }\n}\n";
}

}  // namespace
}  // namespace projtrack::bench

int main(int argc, char** argv) {
  using namespace projtrack::bench;
  gst_init(&argc, &argv);
  std::string out = "docs/real_footage", truth_dir = "bench/real/truth";
  std::vector<std::pair<std::string, std::string>> clip_args;
  int max_frames = 0;
  bool draw = true, variants = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--truth" && i + 1 < argc) {
      truth_dir = argv[++i];
    } else if (a == "--frames" && i + 1 < argc) {
      max_frames = std::atoi(argv[++i]);
    } else if (a == "--variants") {
      variants = true;
    } else if (a == "--only-default") {
      only_default = true;
    } else if (a == "--seeds" && i + 1 < argc) {
      std::ifstream in(argv[++i]);
      std::string line;
      std::getline(in, line);  // the header
      while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string clip, x, y;
        if (std::getline(row, clip, ',') && std::getline(row, x, ',') && std::getline(row, y))
          other_seeds[clip].push_back({std::atoi(x.c_str()), std::atoi(y.c_str())});
      }
    } else if (a == "--no-draw") {
      draw = false;
    } else if (a == "--clip" && i + 1 < argc && std::strchr(argv[i + 1], '=')) {
      const std::string v = argv[++i];
      clip_args.push_back({v.substr(0, v.find('=')), v.substr(v.find('=') + 1)});
    } else {
      std::fprintf(
          stderr,
          "usage: projtrack-real --out DIR [--truth DIR] [--frames N] [--no-draw] [--only-default] "
          "[--variants] [--seeds FILE] "
          "--clip NAME=FILE...\n");
      return 2;
    }
  }
  if (GstElementFactory* f = gst_element_factory_find("projtrack")) {
    gst_object_unref(f);
  } else {
    std::fprintf(stderr, "projtrack-real: the projtrack element is not found (GST_PLUGIN_PATH)\n");
    return 1;
  }
  cv::setNumThreads(1);  // one thread for every tracker (cvtracker's OpenCV included)

  std::vector<std::unique_ptr<Clip>> clips;
  for (const auto& [name, path] : clip_args) {
    auto c = std::make_unique<Clip>();
    c->name = name;
    c->path = std::filesystem::absolute(path).string();
    if (!decode(path, *c, max_frames)) {
      std::fprintf(stderr, "projtrack-real: cannot decode %s\n", path.c_str());
      return 1;
    }
    const std::string truth_path = truth_dir + "/" + name + ".csv";
    if (std::filesystem::exists(truth_path)) {
      c->truth = read_truth(truth_path);
      // The truth was labelled on frames decoded by OpenCV into full-range RGB: the same frames
      // have the same mean luma up to the range mapping (an affine map) and rounding.
      if (c->truth.size() < c->i420.size() || !same_frames(*c)) {
        std::fprintf(stderr, "projtrack-real: %s does not match the frames of %s\n",
                     truth_path.c_str(), path.c_str());
        return 1;
      }
      c->truth.resize(c->i420.size());
    }
    make_buffers(*c);
    std::fprintf(stderr, "projtrack-real: %s: %zu frames, %dx%d%s\n", name.c_str(), c->i420.size(),
                 c->width, c->height, c->truth.empty() ? ", no truth" : "");
    clips.push_back(std::move(c));
  }
  if (variants) {
    const std::size_t originals = clips.size();
    for (std::size_t k = 0; k < originals; ++k) {
      if (clips[k]->truth.empty()) continue;
      for (const char* how : kVariants) {
        clips.push_back(variant(*clips[k], how));
        write_truth(*clips.back(), out + "/truth");
      }
    }
  }

  std::filesystem::create_directories(out);
  runs_csv = std::fopen((out + "/runs.csv").c_str(), "w");
  speed_csv = std::fopen((out + "/speed.csv").c_str(), "w");
  if (!runs_csv || !speed_csv) {
    std::fprintf(stderr, "projtrack-real: cannot write in %s\n", out.c_str());
    return 1;
  }
  std::fprintf(
      runs_csv,
      "clip,tracker,group,frame,status,measured,centroid_x,centroid_y,area,x,y,width,"
      "height,has_pose,position_x,position_y,depth,push,acquired,us,moving_share,scene_share,"
      "detail\n");
  std::fprintf(speed_csv, "clip,resolution,what,median_us,frames\n");

  long steps = 0;
  for (const auto& c : clips) {
    const long n = static_cast<long>(c->i420.size());
    const bool extra = c->variant.empty();  // the overlay and 1080p: for the clips as decoded
    steps += n * (1 + (draw && extra ? (c->truth.empty() ? 1 : 2) : 0) +
                  (c->truth.empty() || !extra ? 0 : 1));
  }
  {
    Progress progress(steps);
    for (const auto& c : clips) run_all(*c, progress);
    for (const auto& c : clips) {
      if (!c->variant.empty()) continue;
      if (draw && !c->truth.empty())
        draw_frames(*c, out + "/frames", "seeded", seed_props(*c), progress);
      if (draw) draw_frames(*c, out + "/frames", "no-seed", kNoSeedProps, progress);
      if (!c->truth.empty()) speed_1080p(*c, progress);
    }
  }
  std::fclose(runs_csv);
  std::fclose(speed_csv);
  write_meta(out, clips);
  clips.clear();
  gst_deinit();
  return 0;
}
