#include "runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "element_harness.hpp"
#include "projtrack/method.hpp"
#include "trackers.hpp"

namespace projtrack::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kNoSeedProps = "acquisition=auto";
// The box trackers on every clip as decoded and on its edge variant; on the other variants the
// fast ones alone (KCF and CSRT cost 20-250 ms a frame: with them on every variant the run would
// not fit in an hour on two cores).
constexpr const char* kAllPeers[] = {"MOSSE", "KCF", "CSRT", "MedianFlow"};
constexpr const char* kFastPeers[] = {"MOSSE", "MedianFlow"};

std::string point_props(const Point2i& p) {
  return "inner-point-x=" + std::to_string(p.x) + " inner-point-y=" + std::to_string(p.y);
}

std::string box_props(const Rect& b) {
  return "start-box=\"<" + std::to_string(b.x) + "," + std::to_string(b.y) + "," +
         std::to_string(b.width) + "," + std::to_string(b.height) + ">\"";
}

bool has_cvtracker() {
  GstElementFactory* f = gst_element_factory_find("cvtracker");
  if (!f) return false;
  gst_object_unref(f);
  return true;
}

using Runs = std::vector<std::pair<Tracker, std::string>>;  // tracker, group

void add_projtrack(const Clip& c, Runs& ts, bool only_default) {
  const bool reduced = only_default || !c.variant.empty();
  const std::string def = default_method();
  const std::string deepest = point_props(*c.starts.deepest);
  for (Method m : kAllMethods) {
    const std::string method(method_name(m));
    if (reduced && method != def) continue;
    ts.push_back({projtrack_tracker(c, "projtrack " + method, "method=" + method + " " + deepest),
                  "projtrack seeded"});
  }
  int q = 0;
  for (const Point2i& p : c.starts.quarters) {
    const std::string at =
        std::to_string(++q) + " at " + std::to_string(p.x) + "," + std::to_string(p.y);
    ts.push_back(
        {projtrack_tracker(c, "projtrack quarter " + at, point_props(p)), "projtrack quarter"});
  }
  if (c.starts.box)
    ts.push_back(
        {projtrack_tracker(c, "projtrack start-box", box_props(*c.starts.box)), "projtrack box"});
}

void add_peers(const Clip& c, Runs& ts) {
  if (!c.starts.box) return;
  const Rect& box = *c.starts.box;
  const bool all = c.variant.empty() || c.variant == "edge";
  if (has_cvtracker()) {
    if (all)
      for (const char* a : kAllPeers) ts.push_back({cvtracker_tracker(c, a, box), "box tracker"});
    else
      for (const char* a : kFastPeers) ts.push_back({cvtracker_tracker(c, a, box), "box tracker"});
  } else {
    std::fprintf(stderr, "projtrack-real: cvtracker not found (gstreamer1.0-opencv)\n");
  }
  ts.push_back({camshift_tracker(c, box), "box tracker"});
}

double micros_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void run_all(const Clip& c, RunsCsv& out, Progress& progress, bool only_default) {
  Runs ts;
  if (c.has_truth()) add_projtrack(c, ts, only_default);
  // No seed: the element finds the object itself. Said explicitly, not left to the default.
  ts.push_back({projtrack_tracker(c, "projtrack no seed", kNoSeedProps), "projtrack no seed"});
  if (c.has_truth() && !only_default) add_peers(c, ts);
  const int n = static_cast<int>(c.frames.size());
  for (int i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < ts.size(); ++k) {
      auto& [t, group] = ts[(k + i) % ts.size()];
      out.write(c, t.name, group, i, t.process(i));
    }
    progress.advance(c.name + " frame " + std::to_string(i));
  }
}

void speed_1080p(const Clip& c, std::FILE* speed_csv, Progress& progress) {
  const int w = 1920, h = 1080;
  const double sx = static_cast<double>(w) / c.width, sy = static_cast<double>(h) / c.height;
  const Point2i p = *c.starts.deepest;
  const std::string seed = point_props({static_cast<int>(p.x * sx), static_cast<int>(p.y * sy)});
  const std::string caps = raw_caps("I420", w, h, c.fps_n, c.fps_d);
  ElementHarness element("projtrack " + seed, caps, false), identity("identity", caps, false);
  std::vector<double> t_copy, t_element, t_identity;
  std::vector<std::uint8_t> copy_target(static_cast<std::size_t>(w) * h * 3 / 2);
  cv::Mat big;
  for (std::size_t i = 0; i < c.frames.size(); ++i) {
    cv::resize(to_bgr(c.frames[i]), big, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
    GstBuffer* b = i420_buffer(from_bgr(big), c.pts[i], GST_CLOCK_TIME_NONE);
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

}  // namespace projtrack::bench
