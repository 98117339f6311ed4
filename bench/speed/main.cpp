// projtrack-speed: the speed targets as ratios measured side by side in one run, one thread
// (./run bench --speed; docs/performance.md). Every contender processes the same decoded frames
// in turn, batch after batch, so a noisy machine slows all of them alike.
//
//   projtrack-speed [--out DIR] [--quick] [--clip FILE] [--only-bounded] [--list-methods]
//
// Writes DIR/speed.csv (output.hpp), DIR/methods.csv and DIR/meta.json. Each section is a file
// of its own (sections.hpp); the frames are clip.hpp's, the timing race.hpp's.
#include <gst/gst.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <string>
#include <thread>
#include <vector>

#include "machine.hpp"
#include "method_list.hpp"
#include "output.hpp"
#include "sections.hpp"

namespace projtrack::bench {
namespace {

struct Args {
  std::string out = "docs/performance";
  std::string clip_path = "/usr/share/doc/opencv-doc/examples/data/Megamind.avi";
  bool quick = false, only_bounded = false, list_methods = false;
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--out" && i + 1 < argc)
      a.out = argv[++i];
    else if (s == "--quick")
      a.quick = true;
    else if (s == "--only-bounded")
      a.only_bounded = true;
    else if (s == "--clip" && i + 1 < argc)
      a.clip_path = argv[++i];
    else if (s == "--list-methods")
      a.list_methods = true;
    else
      return false;
    if (a.list_methods) return true;  // the list alone, whatever follows
  }
  return true;
}

// The element's default method (into kDefaultMethod and a meta row); false when the element is
// not found.
bool read_default_method() {
  GstElementFactory* f = gst_element_factory_find("projtrack");
  if (!f) {
    std::fprintf(stderr, "projtrack-speed: the projtrack element is not found (GST_PLUGIN_PATH)\n");
    return false;
  }
  gst_object_unref(f);
  GstElement* e = gst_element_factory_make("projtrack", nullptr);
  GParamSpec* spec = g_object_class_find_property(G_OBJECT_GET_CLASS(e), "method");
  const GValue* def = g_param_spec_get_default_value(spec);
  GEnumValue* v = g_enum_get_value(G_PARAM_SPEC_ENUM(spec)->enum_class, g_value_get_enum(def));
  kDefaultMethod = v->value_nick;
  gst_object_unref(e);
  row("meta", nullptr, "default method", kDefaultMethod, 1);
  return true;
}

bool have_cvtracker() {
  GstElementFactory* cvt = gst_element_factory_find("cvtracker");
  if (!cvt) {
    std::fprintf(stderr, "projtrack-speed: cvtracker not found (gstreamer1.0-opencv): no MOSSE\n");
    return false;
  }
  gst_object_unref(cvt);
  return true;
}

// Sections 1–6 but the streams: per frame against the peers, the work and outcomes, allocations
// and memory, the cost by object size, the edge stages.
void run_timed_sections(const Args& a, bool cvtracker) {
  const bool quick = a.quick;
  const int rounds = quick ? 3 : 25, batch = quick ? 4 : 12, frames = quick ? 12 : 60;
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}}) {
    std::fprintf(stderr, "projtrack-speed: %dx%d generated\n", w, h);
    auto gen = generated_clip(w, h, 0.10, frames);
    compare_with_peers(*gen, rounds, batch, cvtracker);
    if (w == 640) ordinary_work(*gen);
    std::fprintf(stderr, "projtrack-speed: %dx%d real clip\n", w, h);
    if (auto real = real_clip(a.clip_path, w, h, quick ? 12 : 270)) {
      compare_with_peers(*real, rounds, batch, cvtracker);
      if (w == 640) {
        real_clip_statuses(*real);
        ordinary_work(*real);
      }
    } else {
      std::fprintf(stderr, "projtrack-speed: cannot read %s (opencv-doc): no real clip\n",
                   a.clip_path.c_str());
    }
    if (w == 1920) {
      std::fprintf(stderr, "projtrack-speed: allocations and memory\n");
      allocations_and_memory(*gen, quick ? 300 : 10000);
    }
  }
  const std::vector<double> object_px =
      quick ? std::vector<double>{4000, 30000}
            : std::vector<double>{2000, 5000, 12000, 30000, 60000, 100000};
  std::fprintf(stderr, "projtrack-speed: cost by object size\n");
  cost_by_object_size(object_px, quick ? 2 : 9);
  std::fprintf(stderr, "projtrack-speed: edge stages against OpenCV's\n");
  edge_stages(object_px, rounds, batch);
}

// Sections 7–9: bounded work.
void run_bounded_sections(bool quick) {
  std::fprintf(stderr, "projtrack-speed: bounded work on adversarial content\n");
  const int w = 1920, h = 1080, n = quick ? 3 : 6, reps = quick ? 1 : 3;
  std::vector<std::unique_ptr<Clip>> set;
  for (const synthetic::AdversaryInfo& a : synthetic::kAdversaries) {
    if (quick && a.kind != synthetic::Adversary::Dots15 && a.kind != synthetic::Adversary::Checker1)
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

// Section 6: concurrent streams.
void run_streams_section(bool quick) {
  std::fprintf(stderr, "projtrack-speed: concurrent streams\n");
  auto vga = generated_clip(640, 480, 0.10, 60);
  const int frames_each = quick ? 30 : 600;
  streams_rows(*vga, 1, frames_each);
  streams_rows(*vga, 8, frames_each);
  row("streams", vga.get(), "cores", "count", std::thread::hardware_concurrency());
}

}  // namespace
}  // namespace projtrack::bench

int main(int argc, char** argv) {
  using namespace projtrack::bench;
  Args a;
  if (!parse(argc, argv, a)) {
    std::fprintf(stderr,
                 "usage: projtrack-speed [--out DIR] [--quick] [--clip FILE] [--only-bounded] "
                 "[--list-methods]\n"
                 "  --only-bounded  only the bounded-work sections (adversarial content, extreme "
                 "settings, set_state(NULL) during a heavy frame)\n");
    return 2;
  }
  if (a.list_methods) {
    write_method_list(std::cout);
    return 0;
  }
  g_setenv("G_SLICE", "always-malloc", TRUE);  // GLib's slices counted as allocations too
  gst_init(&argc, &argv);
  cv::setNumThreads(1);  // one thread for every contender (cvtracker's OpenCV included)
  csv = std::fopen((a.out + "/speed.csv").c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "projtrack-speed: cannot write %s/speed.csv\n", a.out.c_str());
    return 1;
  }
  std::fprintf(csv, "section,clip,resolution,what,key,value\n");
  if (!write_method_list(a.out)) {
    std::fprintf(stderr, "projtrack-speed: cannot write %s/methods.csv\n", a.out.c_str());
    return 1;
  }
  const std::string measured = utc_now();
  if (!read_default_method()) return 1;
  const bool cvtracker = have_cvtracker();
  if (!a.only_bounded) run_timed_sections(a, cvtracker);
  run_bounded_sections(a.quick);
  if (!a.only_bounded) run_streams_section(a.quick);
  std::fclose(csv);
  write_meta(a.out, measured);
  gst_deinit();
  return 0;
}
