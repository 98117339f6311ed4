// projtrack-speed: the speed targets as ratios measured side by side in one run, one thread
// (./run bench --speed; docs/performance.md). Every contender processes the same decoded frames
// in turn, batch after batch, so a noisy machine slows all of them alike.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <thread>
#include <vector>

#include "alloc_count.hpp"
#include "method_list.hpp"
#include "peers.hpp"
#include "scene.hpp"
#include "sequence.hpp"
#include "tracker.hpp"

namespace projtrack::bench {
namespace {

using synthetic::frame_at;
using synthetic::make_scene;
using synthetic::Object;
using synthetic::Scene;
using synthetic::SceneSpec;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The same frames in every form a contender needs.
struct Clip {
  std::string name;
  int width = 0, height = 0;
  std::vector<cv::Mat> gray;          // CV_8U
  std::vector<GstBuffer*> i420, rgb;  // what projtrack and cvtracker are given
  std::vector<Point2i> seeds;         // an inner point per frame (the truth when known)
  Rect first_box;                     // the object's box on frame 0 (cvtracker's start)
  double object_share = 0;            // object area / frame area on frame 0 (0: unknown)
  ~Clip() {
    for (GstBuffer* b : i420) gst_buffer_unref(b);
    for (GstBuffer* b : rgb) gst_buffer_unref(b);
  }
};

GstBuffer* buffer_of(const cv::Mat& packed) {
  const gsize n = packed.total() * packed.elemSize();
  GstBuffer* b = gst_buffer_new_allocate(nullptr, n, nullptr);
  gst_buffer_fill(b, 0, packed.data, n);
  return b;
}

void add_frame(Clip& c, const cv::Mat& bgr_or_gray) {
  cv::Mat gray, bgr, rgb, i420;
  if (bgr_or_gray.channels() == 1) {
    gray = bgr_or_gray;
    cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  } else {
    bgr = bgr_or_gray;
    cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  }
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  if (bgr_or_gray.channels() == 1) {  // a grey scene: luma as rendered, neutral chroma
    i420.create(c.height * 3 / 2, c.width, CV_8UC1);
    gray.copyTo(i420.rowRange(0, c.height));
    i420.rowRange(c.height, i420.rows).setTo(128);
  } else {
    cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
    gray = i420.rowRange(0, c.height).clone();  // the luma projtrack will read
  }
  c.gray.push_back(gray.clone());
  c.i420.push_back(buffer_of(i420));
  c.rgb.push_back(buffer_of(rgb));
}

// A sphere covering about `share` of the frame, swinging left and right by `swing` of the frame's
// width (a period of `n` frames, so looping over the frames is smooth motion), fresh sensor
// noise on each frame.
std::unique_ptr<Clip> generated_clip(int w, int h, double share, int n, double swing = 0.12) {
  auto c = std::make_unique<Clip>();
  c->name = "generated";
  c->width = w;
  c->height = h;
  const Scene probe = make_scene(SceneSpec(w, h), {});
  const double scale = std::sqrt(share * w * h / probe.true_area);
  for (int i = 0; i < n; ++i) {
    SceneSpec s = frame_at(Object::Sphere, w / 2 + swing * w * std::sin(2 * M_PI * i / n),
                           h / 2 + swing / 3 * h * std::cos(2 * M_PI * i / n), i, scale);
    s.width = w;
    s.height = h;
    const Scene scene = make_scene(s, {});
    add_frame(*c, scene.image);
    c->seeds.push_back(round_to_pixel(scene.true_centroid));
    if (i == 0) {
      cv::Rect b = cv::boundingRect(scene.mask);
      c->first_box = {b.x, b.y, b.width, b.height};
      c->object_share = scene.true_area / (static_cast<double>(w) * h);
    }
  }
  return c;
}

// A real clip (opencv-doc's Megamind.avi: an animated character on a busy background), resized.
// The object is unknown: projtrack finds one by itself (acquisition=auto), the stock-OpenCV
// peer fills from the frame centre, cvtracker starts from a centred box a tenth of the frame.
std::unique_ptr<Clip> real_clip(const std::string& path, int w, int h, int max_frames) {
  cv::VideoCapture cap(path);
  if (!cap.isOpened()) return nullptr;
  auto c = std::make_unique<Clip>();
  c->name = "real";
  c->width = w;
  c->height = h;
  cv::Mat frame, sized;
  while (static_cast<int>(c->gray.size()) < max_frames && cap.read(frame)) {
    cv::resize(frame, sized, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
    add_frame(*c, sized);
    c->seeds.push_back({w / 2, h / 2});
  }
  const int bw = static_cast<int>(w * std::sqrt(0.1)), bh = static_cast<int>(h * std::sqrt(0.1));
  c->first_box = {(w - bw) / 2, (h - bh) / 2, bw, bh};
  return c->gray.empty() ? nullptr : std::move(c);
}

// One contender: processes frame i of its clip (frames come in order, each contender has its own).
struct Contender {
  Contender(std::string n, std::function<void(int)> f)
      : name(std::move(n)), process(std::move(f)) {}
  std::string name;
  std::function<void(int)> process;
  std::size_t next = 0;
  std::vector<double> per_frame_us;  // one value per round: the batch's mean
};

class Harness {
 public:
  Harness(const std::string& launch, const std::string& caps) {
    h_ = gst_harness_new_parse(launch.c_str());
    gst_harness_set_src_caps_str(h_, caps.c_str());
    bus_ = gst_bus_new();
    gst_bus_set_flushing(bus_, TRUE);  // messages are made and posted, then dropped
    gst_element_set_bus(h_->element, bus_);
  }
  ~Harness() {
    gst_element_set_bus(h_->element, nullptr);
    gst_object_unref(bus_);
    gst_harness_teardown(h_);
  }
  Harness(const Harness&) = delete;
  Harness& operator=(const Harness&) = delete;
  // Pushes one frame and takes it back out; false if the element refused it.
  bool run(GstBuffer* frame) {
    if (gst_harness_push(h_, gst_buffer_ref(frame)) != GST_FLOW_OK) return false;
    GstBuffer* out = gst_harness_pull(h_);
    if (!out) return false;
    gst_buffer_unref(out);
    return true;
  }
  GstElement* element() { return h_->element; }

 private:
  GstHarness* h_;
  GstBus* bus_;
};

std::string caps_of(const char* format, const Clip& c) {
  return std::string("video/x-raw,format=") + format + ",width=" + std::to_string(c.width) +
         ",height=" + std::to_string(c.height) + ",framerate=30/1";
}

std::string projtrack_launch(const std::string& method, const Clip& c) {
  if (c.name == "real") return "projtrack method=" + method + " acquisition=auto";
  return "projtrack method=" + method +
         " acquisition=manual inner-point-x=" + std::to_string(c.seeds[0].x) +
         " inner-point-y=" + std::to_string(c.seeds[0].y);
}

std::string kDefaultMethod;  // the element's own default, read from its property

std::FILE* csv = nullptr;

void row(const std::string& section, const Clip* c, const std::string& what, const std::string& key,
         double value) {
  std::fprintf(csv, "%s,%s,%dx%d,\"%s\",%s,%.6g\n", section.c_str(), c ? c->name.c_str() : "",
               c ? c->width : 0, c ? c->height : 0, what.c_str(), key.c_str(), value);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Rounds of batches, the contenders' order rotated every round.
void race(std::vector<Contender>& cs, const Clip& clip, int rounds, int batch) {
  const std::size_t n = clip.gray.size();
  for (Contender& c : cs)  // warm up: first acquisition, buffers sized
    for (int i = 0; i < batch; ++i) c.process(static_cast<int>(c.next++ % n));
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t k = 0; k < cs.size(); ++k) {
      Contender& c = cs[(k + r) % cs.size()];
      const auto t0 = Clock::now();
      for (int i = 0; i < batch; ++i) c.process(static_cast<int>(c.next++ % n));
      c.per_frame_us.push_back(1e6 * seconds_since(t0) / batch);
    }
  }
}

// Section 1–3: every method in the element against a frame copy and the peers, on one clip.
void compare_with_peers(Clip& clip, int rounds, int batch, bool have_cvtracker) {
  std::vector<Contender> cs;
  std::vector<std::uint8_t> copy_target(gst_buffer_get_size(clip.i420[0]));
  cs.push_back({"frame copy", [&](int i) {
                  GstMapInfo m;
                  gst_buffer_map(clip.i420[i], &m, GST_MAP_READ);
                  std::memcpy(copy_target.data(), m.data, std::min(m.size, copy_target.size()));
                  gst_buffer_unmap(clip.i420[i], &m);
                }});
  std::vector<std::unique_ptr<Harness>> harnesses;
  // What pushing a frame through a harness costs around any element (ours is measured with it).
  harnesses.push_back(std::make_unique<Harness>("identity", caps_of("I420", clip)));
  cs.emplace_back("harness alone (identity)",
                  [h = harnesses.back().get(), &clip](int i) { h->run(clip.i420[i]); });
  for (const MethodInfo& m : kMethods) {
    harnesses.push_back(
        std::make_unique<Harness>(projtrack_launch(m.nick, clip), caps_of("I420", clip)));
    Harness* h = harnesses.back().get();
    cs.push_back({std::string("projtrack ") + m.nick, [h, &clip](int i) { h->run(clip.i420[i]); }});
  }
  OpenCvFloodFill flood;
  cv::Mat edges;
  cs.push_back({"cv::Canny + cv::floodFill", [&](int i) {
                  cv::Canny(clip.gray[i], edges, 50, 150, 3, false);
                  Features f = flood.estimate(edges, clip.seeds[i]);
                  (void)f;
                }});
  if (have_cvtracker) {
    const Rect& b = clip.first_box;
    const std::string launch =
        "cvtracker algorithm=MOSSE draw-rect=false object-initial-x=" + std::to_string(b.x) +
        " object-initial-y=" + std::to_string(b.y) +
        " object-initial-width=" + std::to_string(b.width) +
        " object-initial-height=" + std::to_string(b.height);
    harnesses.push_back(std::make_unique<Harness>(launch, caps_of("RGB", clip)));
    Harness* h = harnesses.back().get();
    cs.push_back({"cvtracker MOSSE", [h, &clip](int i) { h->run(clip.rgb[i]); }});
  }
  race(cs, clip, rounds, batch);
  for (Contender& c : cs) {
    row("per_frame", &clip, c.name, "median_us", median(c.per_frame_us));
    row("per_frame", &clip, c.name, "best_us",
        *std::min_element(c.per_frame_us.begin(), c.per_frame_us.end()));
  }
  // The ratios, round by round (each round's contenders ran back to back), then the median.
  auto ratio = [&](const std::string& a, const std::string& b) {
    const Contender *ca = nullptr, *cb = nullptr;
    for (const Contender& c : cs) {
      if (c.name == a) ca = &c;
      if (c.name == b) cb = &c;
    }
    if (!ca || !cb) return;
    std::vector<double> r;
    for (std::size_t k = 0; k < ca->per_frame_us.size(); ++k)
      r.push_back(ca->per_frame_us[k] / cb->per_frame_us[k]);
    row("ratio", &clip, a + " / " + b, "median", median(r));
  };
  for (const MethodInfo& m : kMethods) {
    const std::string us = std::string("projtrack ") + m.nick;
    ratio(us, "frame copy");
    ratio("cv::Canny + cv::floodFill", us);
    ratio("cvtracker MOSSE", us);
  }
  if (clip.object_share > 0) row("clip", &clip, "object", "share_of_frame", clip.object_share);
  row("clip", &clip, "frames", "count", static_cast<double>(clip.gray.size()));
}

// Section 4: the library's cost against the object's size, at two frame sizes.
void cost_by_object_size(int rounds, bool quick) {
  const std::vector<double> object_px =
      quick ? std::vector<double>{4000, 30000}
            : std::vector<double>{2000, 5000, 12000, 30000, 60000, 100000};
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}}) {
    for (double px : object_px) {
      auto clip = generated_clip(w, h, px / (static_cast<double>(w) * h), 8, 0);  // in place
      std::vector<Contender> cs;
      std::vector<std::unique_ptr<Tracker>> trackers;
      for (Method method : kAllMethods) {
        trackers.push_back(std::make_unique<Tracker>());
        Tracker* t = trackers.back().get();
        TrackerParams tp;
        tp.acquisition = Acquisition::Manual;
        t->seed(clip->seeds[0]);
        cs.push_back({std::string(method_name(method)), [t, method, tp, c = clip.get()](int i) {
                        const ImageView g(c->gray[i].data, c->width, c->height,
                                          static_cast<std::ptrdiff_t>(c->gray[i].step));
                        t->track(g, EdgeParams{}, i / 30.0, method, Params{}, tp);
                      }});
      }
      race(cs, *clip, rounds, 8);
      for (Contender& c : cs) {
        row("size", clip.get(), c.name, "object_px_" + std::to_string(static_cast<int>(px)),
            median(c.per_frame_us));
      }
    }
  }
}

// Section 5: heap allocations per frame in steady state, and memory over 10 000 frames.
long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

void allocations_and_memory(Clip& clip, int frames) {
  const std::size_t n = clip.gray.size();
  for (Method method : kAllMethods) {  // the library alone
    Tracker t;
    TrackerParams tp;
    tp.acquisition = Acquisition::Manual;
    t.seed(clip.seeds[0]);
    auto frame = [&](std::size_t i) {
      const cv::Mat& g = clip.gray[i % n];
      t.track(ImageView(g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step)), EdgeParams{},
              static_cast<double>(i) / 30, method, Params{}, tp);
    };
    for (std::size_t i = 0; i < 2 * n; ++i) frame(i);  // buffers grow to the largest region
    const long before = allocations.load();
    for (std::size_t i = 2 * n; i < 2 * n + 200; ++i) frame(i);
    row("allocations", &clip, "Tracker::track " + std::string(method_name(method)), "per_frame",
        (allocations.load() - before) / 200.0);
  }
  // The element, less what the harness itself allocates around an element that does nothing.
  auto per_frame = [&](const std::string& launch) {
    Harness h(launch, caps_of("I420", clip));
    for (std::size_t i = 0; i < 2 * n; ++i) h.run(clip.i420[i % n]);
    const long before = allocations.load();
    for (std::size_t i = 0; i < 200; ++i) h.run(clip.i420[i % n]);
    return (allocations.load() - before) / 200.0;
  };
  const double identity = per_frame("identity");
  const double with_messages = per_frame(projtrack_launch(kDefaultMethod, clip));
  const double without = per_frame(projtrack_launch(kDefaultMethod, clip) + " post-messages=false");
  row("allocations", &clip, "projtrack element (messages on)", "per_frame",
      with_messages - identity);
  row("allocations", &clip, "projtrack element (post-messages=false)", "per_frame",
      without - identity);

  Harness h(projtrack_launch(kDefaultMethod, clip), caps_of("I420", clip));
  long at_1000 = 0;
  for (int i = 0; i < frames; ++i) {
    h.run(clip.i420[static_cast<std::size_t>(i) % n]);
    if (i + 1 == std::min(1000, frames)) at_1000 = resident_kib();
  }
  row("memory", &clip, "projtrack element", "rss_kib_at_1000", static_cast<double>(at_1000));
  row("memory", &clip, "projtrack element", "rss_kib_at_end", static_cast<double>(resident_kib()));
  row("memory", &clip, "projtrack element", "frames", frames);
}

// Section 6: concurrent 30 fps streams in one process, each a real pipeline with its own
// streaming thread (appsrc ! projtrack ! fakesink), fed as fast as they take frames.
double streams_fps(const Clip& clip, int streams, int frames_each) {
  struct Stream {
    GstElement* pipeline;
    GstElement* src;
  };
  std::vector<Stream> ss;
  for (int s = 0; s < streams; ++s) {
    const std::string launch = "appsrc name=src format=time block=true max-bytes=2000000 caps=\"" +
                               caps_of("I420", clip) + "\" ! " +
                               projtrack_launch(kDefaultMethod, clip) + " ! fakesink sync=false";
    GError* err = nullptr;
    GstElement* p = gst_parse_launch(launch.c_str(), &err);
    if (!p) {
      std::fprintf(stderr, "projtrack-speed: %s\n", err ? err->message : "parse failed");
      g_clear_error(&err);
      return 0;
    }
    ss.push_back({p, gst_bin_get_by_name(GST_BIN(p), "src")});
    gst_element_set_state(p, GST_STATE_PLAYING);
  }
  const auto t0 = Clock::now();
  std::vector<std::thread> feeders;
  for (Stream& s : ss) {
    feeders.emplace_back([&clip, &s, frames_each] {
      const std::size_t n = clip.i420.size();
      for (int i = 0; i < frames_each; ++i) {
        GstBuffer* b = gst_buffer_copy(clip.i420[static_cast<std::size_t>(i) % n]);  // shallow
        GST_BUFFER_PTS(b) = gst_util_uint64_scale(i, GST_SECOND, 30);
        GST_BUFFER_DURATION(b) = GST_SECOND / 30;
        GstFlowReturn ret;
        g_signal_emit_by_name(s.src, "push-buffer", b, &ret);
        gst_buffer_unref(b);
      }
      GstFlowReturn ret;
      g_signal_emit_by_name(s.src, "end-of-stream", &ret);
    });
  }
  for (std::thread& f : feeders) f.join();
  for (Stream& s : ss) {
    GstBus* bus = gst_element_get_bus(s.pipeline);
    GstMessage* m = gst_bus_timed_pop_filtered(
        bus, 120 * GST_SECOND, static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
    if (m) gst_message_unref(m);
    gst_object_unref(bus);
  }
  const double elapsed = seconds_since(t0);
  for (Stream& s : ss) {
    gst_element_set_state(s.pipeline, GST_STATE_NULL);
    gst_object_unref(s.src);
    gst_object_unref(s.pipeline);
  }
  return streams * frames_each / elapsed;
}

// Not a time: what each method makes of real footage with no ground truth. The tracker (as the
// element runs it, acquisition=auto) over the real clip: frames tracked, refused as leaks, lost
// otherwise, and searching.
void real_clip_statuses(const Clip& clip) {
  for (Method method : kAllMethods) {
    Tracker t;
    TrackerParams tp;
    int tracked = 0, leaks = 0, lost = 0, searching = 0, acquisitions = 0;
    for (std::size_t i = 0; i < clip.gray.size(); ++i) {
      const cv::Mat& g = clip.gray[i];
      const TrackResult r =
          t.track(ImageView(g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step)),
                  EdgeParams{}, static_cast<double>(i) / 30, method, Params{}, tp);
      acquisitions += r.acquired;
      if (r.status == Status::Lost) {
        ++(r.detail.find("leak") != std::string::npos ? leaks : lost);
      } else if (r.status == Status::Searching) {
        ++searching;
      } else if (has_features(r.status)) {
        ++tracked;
      }
    }
    const std::string m(method_name(method));
    row("real_statuses", &clip, m, "tracked", tracked);
    row("real_statuses", &clip, m, "refused_as_leak", leaks);
    row("real_statuses", &clip, m, "lost_otherwise", lost);
    row("real_statuses", &clip, m, "searching", searching);
    row("real_statuses", &clip, m, "acquisitions", acquisitions);
  }
}

void write_meta(const std::string& dir) {
  std::ofstream meta(dir + "/meta.json");
  std::string cpu = "unknown";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);) {
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  meta << "{\n  \"cpu\": \"" << cpu << "\",\n  \"cores\": " << std::thread::hardware_concurrency()
       << ",\n  \"opencv\": \"" << CV_VERSION << "\",\n  \"gstreamer\": \"" << gst_version_string()
       << "\",\n  \"opencv_threads\": " << cv::getNumThreads() << "\n}\n";
}

}  // namespace
}  // namespace projtrack::bench

int main(int argc, char** argv) {
  using namespace projtrack::bench;
  std::string out = "docs/performance";
  bool quick = false;
  std::string clip_path = "/usr/share/doc/opencv-doc/examples/data/Megamind.avi";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--quick")
      quick = true;
    else if (a == "--clip" && i + 1 < argc)
      clip_path = argv[++i];
    else if (a == "--list-methods") {
      write_method_list(std::cout);
      return 0;
    } else {
      std::fprintf(stderr,
                   "usage: projtrack-speed [--out DIR] [--quick] [--clip FILE] [--list-methods]\n");
      return 2;
    }
  }
  g_setenv("G_SLICE", "always-malloc", TRUE);  // GLib's slices counted as allocations too
  gst_init(&argc, &argv);
  cv::setNumThreads(1);  // one thread for every contender (cvtracker's OpenCV included)
  csv = std::fopen((out + "/speed.csv").c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "projtrack-speed: cannot write %s/speed.csv\n", out.c_str());
    return 1;
  }
  std::fprintf(csv, "section,clip,resolution,what,key,value\n");
  if (!write_method_list(out)) {
    std::fprintf(stderr, "projtrack-speed: cannot write %s/methods.csv\n", out.c_str());
    return 1;
  }
  GstElementFactory* f = gst_element_factory_find("projtrack");
  if (!f) {
    std::fprintf(stderr, "projtrack-speed: the projtrack element is not found (GST_PLUGIN_PATH)\n");
    return 1;
  }
  gst_object_unref(f);
  {
    GstElement* e = gst_element_factory_make("projtrack", nullptr);
    GParamSpec* spec = g_object_class_find_property(G_OBJECT_GET_CLASS(e), "method");
    const GValue* def = g_param_spec_get_default_value(spec);
    GEnumValue* v = g_enum_get_value(G_PARAM_SPEC_ENUM(spec)->enum_class, g_value_get_enum(def));
    kDefaultMethod = v->value_nick;
    gst_object_unref(e);
    row("meta", nullptr, "default method", kDefaultMethod, 1);
  }
  GstElementFactory* cvt = gst_element_factory_find("cvtracker");
  const bool have_cvtracker = cvt != nullptr;
  if (cvt)
    gst_object_unref(cvt);
  else
    std::fprintf(stderr, "projtrack-speed: cvtracker not found (gstreamer1.0-opencv): no MOSSE\n");

  const int rounds = quick ? 3 : 25, batch = quick ? 4 : 12, frames = quick ? 12 : 60;
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}}) {
    std::fprintf(stderr, "projtrack-speed: %dx%d generated\n", w, h);
    auto gen = generated_clip(w, h, 0.10, frames);
    compare_with_peers(*gen, rounds, batch, have_cvtracker);
    std::fprintf(stderr, "projtrack-speed: %dx%d real clip\n", w, h);
    if (auto real = real_clip(clip_path, w, h, quick ? 12 : 270)) {
      compare_with_peers(*real, rounds, batch, have_cvtracker);
      if (w == 640) real_clip_statuses(*real);
    } else {
      std::fprintf(stderr, "projtrack-speed: cannot read %s (opencv-doc): no real clip\n",
                   clip_path.c_str());
    }
    if (w == 1920) {
      std::fprintf(stderr, "projtrack-speed: allocations and memory\n");
      allocations_and_memory(*gen, quick ? 300 : 10000);
    }
  }
  std::fprintf(stderr, "projtrack-speed: cost by object size\n");
  cost_by_object_size(quick ? 2 : 9, quick);

  std::fprintf(stderr, "projtrack-speed: concurrent streams\n");
  auto vga = generated_clip(640, 480, 0.10, 60);
  const int frames_each = quick ? 30 : 600;
  row("streams", vga.get(), "1 stream", "fps", streams_fps(*vga, 1, frames_each));
  row("streams", vga.get(), "8 streams", "fps", streams_fps(*vga, 8, frames_each));
  row("streams", vga.get(), "cores", "count", std::thread::hardware_concurrency());
  std::fclose(csv);
  write_meta(out);
  gst_deinit();
  return 0;
}
