// projtrack-speed: the speed targets as ratios measured side by side in one run, one thread
// (./run bench --speed; docs/performance.md). Every contender processes the same decoded frames
// in turn, batch after batch, so a noisy machine slows all of them alike.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <thread>
#include <unordered_set>
#include <vector>

#include "adversarial.hpp"
#include "alloc_count.hpp"
#include "edges/box_blur.hpp"
#include "machine.hpp"
#include "method_list.hpp"
#include "peers.hpp"
#include "edges/canny.hpp"
#include "projtrack/tracker.hpp"
#include "scene.hpp"
#include "sequence.hpp"
#include "tracker/edge_region.hpp"

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
  // `keep_status`: the status of the element's last message is kept (status()); else messages
  // are made and posted, then dropped.
  Harness(const std::string& launch, const std::string& caps, bool keep_status = false) {
    h_ = gst_harness_new_parse(launch.c_str());
    gst_harness_set_src_caps_str(h_, caps.c_str());
    bus_ = gst_bus_new();
    if (keep_status)
      gst_bus_set_sync_handler(bus_, status_of, &status_, nullptr);
    else
      gst_bus_set_flushing(bus_, TRUE);
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
  // Forgets the track (the element's reset signal), as a new stream would start.
  void reset() {
    GstIterator* it =
        gst_bin_iterate_all_by_element_factory_name(GST_BIN(h_->element), "projtrack");
    GValue v = G_VALUE_INIT;
    if (gst_iterator_next(it, &v) == GST_ITERATOR_OK) {
      g_signal_emit_by_name(g_value_get_object(&v), "reset");
      g_value_unset(&v);
    }
    gst_iterator_free(it);
  }
  const std::string& status() const { return status_; }

 private:
  static GstBusSyncReply status_of(GstBus*, GstMessage* m, gpointer status) {
    if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
      const char* s = gst_structure_get_string(gst_message_get_structure(m), "status");
      *static_cast<std::string*>(status) = s ? s : "";
    }
    gst_message_unref(m);
    return GST_BUS_DROP;
  }
  GstHarness* h_;
  GstBus* bus_;
  std::string status_;
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
// The element with every property at its default (the appearance model): what users run.
const std::string kElementDefault = "projtrack element default";

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

// The median over rounds of a's time / b's (each round's contenders ran back to back).
double median_ratio(const Contender& a, const Contender& b) {
  std::vector<double> r;
  for (std::size_t k = 0; k < a.per_frame_us.size() && k < b.per_frame_us.size(); ++k)
    r.push_back(a.per_frame_us[k] / b.per_frame_us[k]);
  return median(r);
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
  // Each method on the edges alone (object-model=edges: the estimator's own job, which is the
  // stock-OpenCV peer's too), and the element as users run it (the appearance model).
  for (const MethodInfo& m : kMethods) {
    harnesses.push_back(std::make_unique<Harness>(
        projtrack_launch(m.nick, clip) + " object-model=edges", caps_of("I420", clip)));
    Harness* h = harnesses.back().get();
    cs.push_back({std::string("projtrack ") + m.nick, [h, &clip](int i) { h->run(clip.i420[i]); }});
  }
  harnesses.push_back(
      std::make_unique<Harness>(projtrack_launch(kDefaultMethod, clip), caps_of("I420", clip)));
  cs.push_back(
      {kElementDefault, [h = harnesses.back().get(), &clip](int i) { h->run(clip.i420[i]); }});
  OpenCvFloodFill flood;
  cv::Mat edges;
  cs.push_back({"cv::Canny + cv::floodFill", [&](int i) {
                  cv::Canny(clip.gray[i], edges, EdgeParams{}.low, EdgeParams{}.high, 3, false);
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
  auto ratio = [&](const std::string& a, const std::string& b) {
    const Contender *ca = nullptr, *cb = nullptr;
    for (const Contender& c : cs) {
      if (c.name == a) ca = &c;
      if (c.name == b) cb = &c;
    }
    if (ca && cb) row("ratio", &clip, a + " / " + b, "median", median_ratio(*ca, *cb));
  };
  for (const MethodInfo& m : kMethods) {
    const std::string us = std::string("projtrack ") + m.nick;
    ratio(us, "frame copy");
    ratio("cv::Canny + cv::floodFill", us);
    ratio("cvtracker MOSSE", us);
  }
  ratio(kElementDefault, "frame copy");
  ratio("cvtracker MOSSE", kElementDefault);
  if (clip.object_share > 0) row("clip", &clip, "object", "share_of_frame", clip.object_share);
  row("clip", &clip, "start box", "share_of_frame",
      static_cast<double>(clip.first_box.width) * clip.first_box.height /
          (static_cast<double>(clip.width) * clip.height));
  row("clip", &clip, "frames", "count", static_cast<double>(clip.gray.size()));
}

// Section 4: the library's cost against the object's size, at two frame sizes.
void cost_by_object_size(const std::vector<double>& object_px, int rounds) {
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

// Our box blur and Canny against cv::blur and cv::Canny, side by side on the same crops of the
// same frames: the regions the tracker asks for around objects of each size (and whole frames,
// what searching costs). Canny runs on the blurred crop, with the element's thresholds.
void edge_stages(const std::vector<double>& object_px, int rounds, int batch) {
  const EdgeParams ep;
  const Method method = method_from_name(kDefaultMethod).value_or(Method::GridFilling);
  struct Case {
    std::unique_ptr<Clip> clip;
    Rect region;
    double object_px;  // 0: the whole frame
  };
  std::vector<Case> cases;
  for (double px : object_px) {
    auto clip = generated_clip(640, 480, px / (640.0 * 480), 8, 0);
    // The region the edges model computes edges in around the object at rest.
    const Rect region = edge_region(clip->first_box, {0, 0}, method, Params{}, TrackerParams{},
                                    clip->width, clip->height);
    cases.push_back({std::move(clip), region, px});
  }
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}})
    cases.push_back({generated_clip(w, h, 0.10, 4, 0), Rect{0, 0, w, h}, 0});
  for (const Case& k : cases) {
    const Clip& clip = *k.clip;
    const Rect region = k.region;
    const cv::Rect roi(region.x, region.y, region.width, region.height);
    std::vector<cv::Mat> crops, blurred;  // contiguous, as a region's buffers are
    for (const cv::Mat& g : clip.gray) {
      crops.push_back(g(roi).clone());
      cv::Mat b;
      cv::blur(crops.back(), b, {3, 3}, {-1, -1}, cv::BORDER_REPLICATE);
      blurred.push_back(b);
    }
    cv::Mat out(region.height, region.width, CV_8U), edges;
    CannyDetector canny;
    const auto view = [](const cv::Mat& m) {
      return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
    };
    std::vector<Contender> cs;
    cs.push_back({"projtrack box blur", [&](int i) {
                    box_blur3(view(crops[i]), {0, 0, region.width, region.height}, out.data,
                              static_cast<std::ptrdiff_t>(out.step));
                  }});
    cs.push_back({"cv::blur", [&](int i) {
                    cv::blur(crops[i], out, {3, 3}, {-1, -1}, cv::BORDER_REPLICATE);
                  }});
    cs.push_back(
        {"projtrack Canny", [&](int i) { canny.detect(view(blurred[i]), ep.low, ep.high); }});
    cs.push_back(
        {"cv::Canny", [&](int i) { cv::Canny(blurred[i], edges, ep.low, ep.high, 3, false); }});
    race(cs, clip, rounds, batch);
    const std::string key =
        "region_" + std::to_string(region.width) + "x" + std::to_string(region.height);
    row("edge_region", &clip, key, "object_px", k.object_px);
    for (const Contender& c : cs) row("edge_stages", &clip, c.name, key, median(c.per_frame_us));
    row("edge_ratio", &clip, "cv::blur / projtrack box blur", key, median_ratio(cs[1], cs[0]));
    row("edge_ratio", &clip, "cv::Canny / projtrack Canny", key, median_ratio(cs[3], cs[2]));
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
  constexpr int kCounted = 200;  // frames whose allocations are counted, after warm-up
  const int mark = std::min(1000, frames / 2);  // memory is compared from here to the last frame
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
    for (std::size_t i = 2 * n; i < 2 * n + kCounted; ++i) frame(i);
    row("allocations", &clip, "Tracker::track " + std::string(method_name(method)), "per_frame",
        static_cast<double>(allocations.load() - before) / kCounted);
  }
  // The element, less what the harness itself allocates around an element that does nothing.
  auto per_frame = [&](const std::string& launch) {
    Harness h(launch, caps_of("I420", clip));
    for (std::size_t i = 0; i < 2 * n; ++i) h.run(clip.i420[i % n]);
    const long before = allocations.load();
    for (std::size_t i = 0; i < kCounted; ++i) h.run(clip.i420[i % n]);
    return static_cast<double>(allocations.load() - before) / kCounted;
  };
  const double identity = per_frame("identity");
  const double with_messages = per_frame(projtrack_launch(kDefaultMethod, clip));
  const double without = per_frame(projtrack_launch(kDefaultMethod, clip) + " post-messages=false");
  row("allocations", &clip, "projtrack element (messages on)", "per_frame",
      with_messages - identity);
  row("allocations", &clip, "projtrack element (post-messages=false)", "per_frame",
      without - identity);
  row("allocation_count", &clip, "frames counted", "count", kCounted);

  Harness h(projtrack_launch(kDefaultMethod, clip), caps_of("I420", clip));
  long at_mark = 0;
  for (int i = 0; i < frames; ++i) {
    h.run(clip.i420[static_cast<std::size_t>(i) % n]);
    if (i + 1 == mark) at_mark = resident_kib();
  }
  row("memory", &clip, "projtrack element", "mark_frames", mark);
  row("memory", &clip, "projtrack element", "rss_kib_at_mark", static_cast<double>(at_mark));
  row("memory", &clip, "projtrack element", "rss_kib_at_end", static_cast<double>(resident_kib()));
  row("memory", &clip, "projtrack element", "frames", frames);
}

// Section 6: concurrent 30 fps streams in one process, each a real pipeline with its own
// streaming thread (appsrc ! projtrack ! fakesink), fed as fast as they take frames. What counts
// is a frame tracked: its projtrack message arrived with a status that carries features. Pushes
// the source refused, streams that did not finish in time and errors are counted too.
struct StreamsResult {
  long pushed = 0, refused = 0;    // buffers offered, and those the source did not take
  long messages = 0, tracked = 0;  // projtrack messages, and those with a tracking status
  int timeouts = 0, errors = 0;    // streams with no end of stream in time, or an error
  double seconds = 0;
};

GstBusSyncReply count_message(GstBus*, GstMessage* m, gpointer data) {
  if (GST_MESSAGE_TYPE(m) != GST_MESSAGE_ELEMENT || !gst_message_has_name(m, "projtrack"))
    return GST_BUS_PASS;
  static const std::unordered_set<std::string> tracking = [] {
    std::unordered_set<std::string> names;
    for (int s = 0; s <= static_cast<int>(kLastTrackStatus); ++s)
      if (has_features(static_cast<TrackStatus>(s)))
        names.insert(std::string(status_name(static_cast<TrackStatus>(s))));
    return names;
  }();
  auto* counts = static_cast<std::atomic<long>*>(data);  // messages, tracked
  const char* status = gst_structure_get_string(gst_message_get_structure(m), "status");
  ++counts[0];
  if (status && tracking.count(status)) ++counts[1];
  gst_message_unref(m);
  return GST_BUS_DROP;  // counted where it was posted; nothing piles up on the bus
}

StreamsResult run_streams(const Clip& clip, int streams, int frames_each, int timeout_s) {
  struct Stream {
    GstElement* pipeline;
    GstElement* src;
    std::atomic<long> counts[2] = {0, 0};
    long refused = 0;
  };
  StreamsResult res;
  std::vector<std::unique_ptr<Stream>> ss;
  for (int s = 0; s < streams; ++s) {
    const std::string launch = "appsrc name=src format=time block=true max-bytes=2000000 caps=\"" +
                               caps_of("I420", clip) + "\" ! " +
                               projtrack_launch(kDefaultMethod, clip) + " ! fakesink sync=false";
    GError* err = nullptr;
    GstElement* p = gst_parse_launch(launch.c_str(), &err);
    if (!p) {
      std::fprintf(stderr, "projtrack-speed: %s\n", err ? err->message : "parse failed");
      g_clear_error(&err);
      ++res.errors;
      continue;
    }
    auto stream = std::make_unique<Stream>();
    stream->pipeline = p;
    stream->src = gst_bin_get_by_name(GST_BIN(p), "src");
    GstBus* bus = gst_element_get_bus(p);
    gst_bus_set_sync_handler(bus, count_message, stream->counts, nullptr);
    gst_object_unref(bus);
    gst_element_set_state(p, GST_STATE_PLAYING);
    ss.push_back(std::move(stream));
  }
  const auto t0 = Clock::now();
  std::vector<std::thread> feeders;
  for (auto& s : ss) {
    feeders.emplace_back([&clip, s = s.get(), frames_each] {
      const std::size_t n = clip.i420.size();
      for (int i = 0; i < frames_each; ++i) {
        GstBuffer* b = gst_buffer_copy(clip.i420[static_cast<std::size_t>(i) % n]);  // shallow
        GST_BUFFER_PTS(b) = gst_util_uint64_scale(i, GST_SECOND, 30);
        GST_BUFFER_DURATION(b) = GST_SECOND / 30;
        GstFlowReturn ret = GST_FLOW_ERROR;
        g_signal_emit_by_name(s->src, "push-buffer", b, &ret);
        gst_buffer_unref(b);
        s->refused += ret != GST_FLOW_OK;
      }
      GstFlowReturn ret;
      g_signal_emit_by_name(s->src, "end-of-stream", &ret);
    });
  }
  for (std::thread& f : feeders) f.join();
  for (auto& s : ss) {
    GstBus* bus = gst_element_get_bus(s->pipeline);
    GstMessage* m = gst_bus_timed_pop_filtered(
        bus, timeout_s * GST_SECOND,
        static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
    if (!m) {
      ++res.timeouts;
    } else {
      res.errors += GST_MESSAGE_TYPE(m) == GST_MESSAGE_ERROR;
      gst_message_unref(m);
    }
    gst_object_unref(bus);
  }
  res.seconds = seconds_since(t0);
  for (auto& s : ss) {
    gst_element_set_state(s->pipeline, GST_STATE_NULL);
    res.pushed += frames_each;
    res.refused += s->refused;
    res.messages += s->counts[0];
    res.tracked += s->counts[1];
    gst_object_unref(s->src);
    gst_object_unref(s->pipeline);
  }
  return res;
}

void streams_rows(const Clip& clip, int streams, int frames_each) {
  constexpr int kTimeoutSeconds = 120;
  const StreamsResult r = run_streams(clip, streams, frames_each, kTimeoutSeconds);
  const std::string what = std::to_string(streams) + (streams == 1 ? " stream" : " streams");
  row("streams", &clip, what, "streams", streams);
  row("streams", &clip, what, "fps", r.tracked / r.seconds);  // frames tracked per second
  row("streams", &clip, what, "frames_pushed", static_cast<double>(r.pushed));
  row("streams", &clip, what, "pushes_refused", static_cast<double>(r.refused));
  row("streams", &clip, what, "messages", static_cast<double>(r.messages));
  row("streams", &clip, what, "frames_tracked", static_cast<double>(r.tracked));
  row("streams", &clip, what, "timeouts", r.timeouts);
  row("streams", &clip, what, "timeout_s", kTimeoutSeconds);
  row("streams", &clip, what, "errors", r.errors);
  row("streams", &clip, what, "seconds", r.seconds);
}

// Sections 7–9: bounded work (issue 16). Every frame is timed alone; a configuration runs its
// sequence `reps` times in the same element (the track reset between runs), and a frame's time is
// its least over the runs: what the frame costs, without the machine's noise (other processes on
// the shared cores only ever add). The worst frame is the largest of those; an ordinary frame the
// median of the same on the generated clip.

struct FrameTimes {
  std::vector<double> us;               // per frame: the least over the runs
  std::map<std::string, int> statuses;  // of the last run, frames per status
};

FrameTimes time_frames(const std::string& launch, const Clip& c, int reps) {
  Harness h(launch, caps_of("I420", c), true);
  FrameTimes t;
  t.us.assign(c.i420.size(), HUGE_VAL);
  for (int r = 0; r < reps; ++r) {
    h.reset();
    if (r + 1 == reps) t.statuses.clear();
    for (std::size_t i = 0; i < c.i420.size(); ++i) {
      const auto t0 = Clock::now();
      const bool ran = h.run(c.i420[i]);
      const double us = 1e6 * seconds_since(t0);
      t.us[i] = ran ? std::min(t.us[i], us) : NAN;
      if (r + 1 == reps) ++t.statuses[h.status()];
    }
  }
  return t;
}

std::unique_ptr<Clip> adversarial_clip(const synthetic::AdversaryInfo& a, int w, int h, int n) {
  auto c = std::make_unique<Clip>();
  c->name = a.name;
  c->width = w;
  c->height = h;
  for (int i = 0; i < n; ++i) {
    add_frame(*c, synthetic::adversarial_frame(a.kind, w, h, i));
    c->seeds.push_back({w / 2, h / 2});
  }
  return c;
}

void status_rows(const std::string& section, const Clip& c, const std::string& what,
                 const FrameTimes& t) {
  for (const auto& [status, n] : t.statuses)
    row(section, &c, what, "status_" + (status.empty() ? std::string("none") : status), n);
}

// Section 7: the element with its defaults and each method, on the adversarial set (from no
// point, acquisition=auto, and from a point at the centre), against the same on ordinary content
// (the generated clip: a sphere tracked from the frame's centre).
void adversarial_defaults(const std::vector<std::unique_ptr<Clip>>& set, const Clip& ordinary,
                          int reps) {
  const std::string centre = " inner-point-x=" + std::to_string(ordinary.width / 2) +
                             " inner-point-y=" + std::to_string(ordinary.height / 2);
  for (const MethodInfo& m : kMethods) {
    const std::string base = std::string("projtrack method=") + m.nick;
    const FrameTimes o = time_frames(base, ordinary, reps);
    row("adversarial", &ordinary, m.nick, "median_us", median(o.us));
    for (const auto& [mode, props] : {std::pair{"auto", std::string()}, {"seeded", centre}}) {
      for (const auto& c : set) {
        const FrameTimes t = time_frames(base + props, *c, reps);
        const std::string what = std::string(m.nick) + " " + mode;
        row("adversarial", c.get(), what, "worst_us", *std::max_element(t.us.begin(), t.us.end()));
        status_rows("adversarial", *c, what, t);
      }
    }
  }
}

// Section 8: settings at their extremes (every value valid; the default max-work), on the
// adversarial set and the ordinary clip.
void extreme_settings(const std::vector<std::unique_ptr<Clip>>& set, const Clip& ordinary, int reps,
                      bool quick) {
  const std::string centre = " inner-point-x=" + std::to_string(ordinary.width / 2) +
                             " inner-point-y=" + std::to_string(ordinary.height / 2);
  std::vector<std::string> settings = {
      "object-model=edges method=pixel-filling",
      "object-model=edges method=gap-tolerant-filling grid-size=1 max-gap=15" + centre,
      "object-model=edges method=recursive-ray-casting rays=32 recursion=4",
  };
  if (!quick) {
    for (const std::string& more : {
             std::string("object-model=edges method=pixel-filling") + centre,
             std::string("object-model=edges method=grid-filling grid-size=1"),
             std::string("object-model=edges method=gap-tolerant-filling grid-size=1 max-gap=15"),
             std::string("object-model=edges method=recursive-ray-casting rays=1024 recursion=2"),
             std::string("object-model=edges method=recursive-ray-casting rays=100 recursion=2 "
                         "max-iterations=1000 convergence=0") +
                 centre,
             std::string("object-model=edges method=rasterized-ray-casting rays=1024 recursion=1 "
                         "block-size=1 max-iterations=1000 convergence=0") +
                 centre,
             std::string("object-model=edges method=iterative-ray-casting rays=1024 "
                         "max-iterations=1000 convergence=0") +
                 centre,
             std::string("object-model=edges acquisition=center method=pixel-filling blur=0 "
                         "edge-threshold-low=10000 edge-threshold-high=10000"),
             std::string("object-model=edges edge-detector=sobel edge-threshold-low=0 blur=16"),
             std::string("method=pixel-filling rays=1024 blur=16") + centre,
             std::string("method=rasterized-ray-casting rays=1024 recursion=1 block-size=1 "
                         "max-iterations=1000 convergence=0"),
         })
      settings.push_back(more);
  }
  for (const std::string& props : settings) {
    const std::string launch = "projtrack " + props;
    const std::string what = props;
    const FrameTimes o = time_frames(launch, ordinary, reps);
    row("extreme", &ordinary, what, "worst_us", *std::max_element(o.us.begin(), o.us.end()));
    status_rows("extreme", ordinary, what, o);
    for (const auto& c : set) {
      const FrameTimes t = time_frames(launch, *c, reps);
      row("extreme", c.get(), what, "worst_us", *std::max_element(t.us.begin(), t.us.end()));
      status_rows("extreme", *c, what, t);
    }
  }
}

// Section 9: gst_element_set_state(NULL) on a pipeline whose element is in a frame that would take
// minutes (no work limit: max-work=0; a million rays per cast on a uniform 1080p frame, so every
// ray crosses the frame): the time set_state takes to return, and the status the frame ended with.
struct InterruptTrial {
  double latency_us = NAN;
  std::string status;
};

InterruptTrial interrupt_trial(const Clip& c, int wait_ms) {
  InterruptTrial trial;
  const std::string launch =
      "appsrc name=src format=time caps=\"" + caps_of("I420", c) +
      "\" ! projtrack name=t object-model=edges method=recursive-ray-casting rays=1024 "
      "recursion=2 max-iterations=1000 convergence=0 max-work=0 acquisition=manual "
      "inner-point-x=" +
      std::to_string(c.width / 2) + " inner-point-y=" + std::to_string(c.height / 2) +
      " ! fakesink sync=false";
  GstElement* p = gst_parse_launch(launch.c_str(), nullptr);
  if (!p) return trial;
  GstElement* src = gst_bin_get_by_name(GST_BIN(p), "src");
  GstElement* t = gst_bin_get_by_name(GST_BIN(p), "t");
  struct Shared {
    std::mutex m;
    std::condition_variable cv;
    bool entered = false;
    std::string status;
  } shared;
  // The buffer is in the element's chain function (its stream lock held) when the probe runs.
  GstPad* sink = gst_element_get_static_pad(t, "sink");
  gst_pad_add_probe(
      sink, GST_PAD_PROBE_TYPE_BUFFER,
      [](GstPad*, GstPadProbeInfo*, gpointer data) {
        auto* sh = static_cast<Shared*>(data);
        std::lock_guard<std::mutex> lock(sh->m);
        sh->entered = true;
        sh->cv.notify_all();
        return GST_PAD_PROBE_OK;
      },
      &shared, nullptr);
  gst_object_unref(sink);
  GstBus* bus = gst_element_get_bus(p);
  gst_bus_set_sync_handler(
      bus,
      [](GstBus*, GstMessage* m, gpointer data) {
        if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
          auto* sh = static_cast<Shared*>(data);
          const char* s = gst_structure_get_string(gst_message_get_structure(m), "status");
          std::lock_guard<std::mutex> lock(sh->m);
          sh->status = s ? s : "";
        }
        gst_message_unref(m);
        return GST_BUS_DROP;
      },
      &shared, nullptr);
  gst_object_unref(bus);
  gst_element_set_state(p, GST_STATE_PLAYING);
  GstFlowReturn ret;
  g_signal_emit_by_name(src, "push-buffer", c.i420[0], &ret);
  {
    std::unique_lock<std::mutex> lock(shared.m);
    shared.cv.wait_for(lock, std::chrono::seconds(30), [&] { return shared.entered; });
  }
  // Well inside the frame (which would take minutes), then stop.
  std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
  const auto t0 = Clock::now();
  gst_element_set_state(p, GST_STATE_NULL);
  trial.latency_us = 1e6 * seconds_since(t0);
  {
    std::lock_guard<std::mutex> lock(shared.m);
    trial.status = shared.entered ? shared.status : "not started";
  }
  gst_object_unref(t);
  gst_object_unref(src);
  gst_object_unref(p);
  return trial;
}

void interrupt_latency(int trials) {
  auto c = std::make_unique<Clip>();
  c->name = "uniform";
  c->width = 1920;
  c->height = 1080;
  add_frame(*c, cv::Mat(1080, 1920, CV_8U, cv::Scalar(128)));
  std::vector<double> us;
  int interrupted = 0;
  for (int i = 0; i < trials; ++i) {
    const InterruptTrial t = interrupt_trial(*c, 50 + 25 * (i % 4));
    us.push_back(t.latency_us);
    interrupted += t.status == "interrupted";
  }
  const std::string what = "set_state(NULL) during a heavy frame";
  row("interrupt", c.get(), what, "latency_us_median", median(us));
  row("interrupt", c.get(), what, "latency_us_max", *std::max_element(us.begin(), us.end()));
  row("interrupt", c.get(), what, "trials", trials);
  row("interrupt", c.get(), what, "frames_interrupted", interrupted);
}

// Not a time: the work each frame of ordinary content needs (TrackResult::work, a multiple of the
// frame's pixels), with no limit, for both object models and every method (acquisition=auto, the
// element's other defaults); and what the default budget changes there: the frames that run out,
// and those whose outcome (status, centroid, area) differs from the unlimited run's.
void ordinary_work(const Clip& clip) {
  const double pixels = static_cast<double>(clip.width) * clip.height;
  for (ObjectModelKind model : {ObjectModelKind::Appearance, ObjectModelKind::Edges}) {
    for (Method method : kAllMethods) {
      TrackerParams unlimited, limited;
      unlimited.model = limited.model = model;
      unlimited.max_work = 0;
      Tracker a, b;
      std::vector<double> work;
      int over = 0, changed = 0;
      for (std::size_t i = 0; i < clip.gray.size(); ++i) {
        const cv::Mat& g = clip.gray[i];
        const ImageView v(g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step));
        const double t = static_cast<double>(i) / 30;
        const TrackResult ra = a.track(v, EdgeParams{}, t, method, Params{}, unlimited);
        const TrackResult rb = b.track(v, EdgeParams{}, t, method, Params{}, limited);
        work.push_back(static_cast<double>(ra.work) / pixels);
        over += rb.status == TrackStatus::OverBudget;
        changed += ra.status != rb.status || ra.features.centroid.x != rb.features.centroid.x ||
                   ra.features.centroid.y != rb.features.centroid.y ||
                   ra.features.area != rb.features.area;
      }
      std::sort(work.begin(), work.end());
      const std::string what =
          std::string(model == ObjectModelKind::Edges ? "edges " : "appearance ") +
          std::string(method_name(method));
      row("ordinary_work", &clip, what, "median_x", median(work));
      row("ordinary_work", &clip, what, "p99_x", work[work.size() * 99 / 100]);
      row("ordinary_work", &clip, what, "max_x", work.back());
      row("ordinary_work", &clip, what, "over_budget_frames", over);
      row("ordinary_work", &clip, what, "changed_frames", changed);
      row("ordinary_work", &clip, what, "frames", static_cast<double>(work.size()));
    }
  }
  row("ordinary_work", &clip, "default max-work", "x", TrackerParams{}.max_work);
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
      if (r.status == TrackStatus::Lost) {
        ++(r.detail.find("leak") != std::string::npos ? leaks : lost);
      } else if (r.status == TrackStatus::Searching) {
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

void write_meta(const std::string& dir, const std::string& measured) {
  std::ofstream meta(dir + "/meta.json");
  meta << "{\n  \"measured\": \"" << measured << "\",\n  \"cpu\": \"" << cpu_model()
       << "\",\n  \"cores\": " << std::thread::hardware_concurrency() << ",\n  \"opencv\": \""
       << CV_VERSION << "\",\n  \"gstreamer\": \"" << gst_version_string()
       << "\",\n  \"opencv_threads\": " << cv::getNumThreads()
       << ",\n  \"edge_margin\": " << TrackerParams{}.edge_margin
       << ",\n  \"least_margin_px\": " << kLeastEdgeMargin << ",\n  \"canny\": ["
       << EdgeParams{}.low << ", " << EdgeParams{}.high << "]\n}\n";
}

}  // namespace
}  // namespace projtrack::bench

int main(int argc, char** argv) {
  using namespace projtrack::bench;
  std::string out = "docs/performance";
  bool quick = false, only_bounded = false;
  std::string clip_path = "/usr/share/doc/opencv-doc/examples/data/Megamind.avi";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--quick")
      quick = true;
    else if (a == "--only-bounded")
      only_bounded = true;
    else if (a == "--clip" && i + 1 < argc)
      clip_path = argv[++i];
    else if (a == "--list-methods") {
      write_method_list(std::cout);
      return 0;
    } else {
      std::fprintf(stderr,
                   "usage: projtrack-speed [--out DIR] [--quick] [--clip FILE] [--only-bounded] "
                   "[--list-methods]\n"
                   "  --only-bounded  only the bounded-work sections (adversarial content, extreme "
                   "settings, set_state(NULL) during a heavy frame)\n");
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
  const std::string measured = utc_now();
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
    if (only_bounded) break;
    std::fprintf(stderr, "projtrack-speed: %dx%d generated\n", w, h);
    auto gen = generated_clip(w, h, 0.10, frames);
    compare_with_peers(*gen, rounds, batch, have_cvtracker);
    if (w == 640) ordinary_work(*gen);
    std::fprintf(stderr, "projtrack-speed: %dx%d real clip\n", w, h);
    if (auto real = real_clip(clip_path, w, h, quick ? 12 : 270)) {
      compare_with_peers(*real, rounds, batch, have_cvtracker);
      if (w == 640) {
        real_clip_statuses(*real);
        ordinary_work(*real);
      }
    } else {
      std::fprintf(stderr, "projtrack-speed: cannot read %s (opencv-doc): no real clip\n",
                   clip_path.c_str());
    }
    if (w == 1920) {
      std::fprintf(stderr, "projtrack-speed: allocations and memory\n");
      allocations_and_memory(*gen, quick ? 300 : 10000);
    }
  }
  const std::vector<double> object_px =
      quick ? std::vector<double>{4000, 30000}
            : std::vector<double>{2000, 5000, 12000, 30000, 60000, 100000};
  if (!only_bounded) {
    std::fprintf(stderr, "projtrack-speed: cost by object size\n");
    cost_by_object_size(object_px, quick ? 2 : 9);
    std::fprintf(stderr, "projtrack-speed: edge stages against OpenCV's\n");
    edge_stages(object_px, rounds, batch);
  }

  {
    std::fprintf(stderr, "projtrack-speed: bounded work on adversarial content\n");
    const int w = 1920, h = 1080, n = quick ? 3 : 6, reps = quick ? 1 : 3;
    std::vector<std::unique_ptr<Clip>> set;
    for (const projtrack::synthetic::AdversaryInfo& a : projtrack::synthetic::kAdversaries) {
      if (quick && a.kind != projtrack::synthetic::Adversary::Dots15 &&
          a.kind != projtrack::synthetic::Adversary::Checker1)
        continue;
      set.push_back(adversarial_clip(a, w, h, n));
    }
    auto ordinary = generated_clip(w, h, 0.10, quick ? 6 : 30);
    adversarial_defaults(set, *ordinary, reps);
    std::fprintf(stderr, "projtrack-speed: extreme settings\n");
    extreme_settings(set, *ordinary, reps, quick);
    std::fprintf(stderr, "projtrack-speed: set_state(NULL) during a heavy frame\n");
    interrupt_latency(quick ? 2 : 8);
  }

  if (!only_bounded) {
    std::fprintf(stderr, "projtrack-speed: concurrent streams\n");
    auto vga = generated_clip(640, 480, 0.10, 60);
    const int frames_each = quick ? 30 : 600;
    streams_rows(*vga, 1, frames_each);
    streams_rows(*vga, 8, frames_each);
    row("streams", vga.get(), "cores", "count", std::thread::hardware_concurrency());
  }
  std::fclose(csv);
  write_meta(out, measured);
  gst_deinit();
  return 0;
}
