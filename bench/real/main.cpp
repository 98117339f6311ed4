// projtrack-real: every tracker on real footage, side by side on the same decoded frames
// (./run bench --real; docs/real_footage.md). The clips, their variants and where each run starts
// are prepare.py's plan (bench/real/clip_set.py lists the set).
//
//   projtrack-real --plan DIR --out DIR [--only-default] [--render FILE]
//
// Writes DIR/runs.csv (one row per clip, tracker and frame), DIR/speed.csv (the clips as decoded
// scaled to 1080p beside a frame copy) and DIR/meta.json. With --render FILE (the report's
// requests), only DIR/frames/<clip>/<run>/NNN.jpg: the frames of the contact sheets.
#include <gst/gst.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <set>
#include <string>
#include <vector>

#include "output.hpp"
#include "plan.hpp"
#include "progress.hpp"
#include "render.hpp"
#include "runner.hpp"

namespace projtrack::bench {
namespace {

struct Args {
  std::string plan_dir, out;
  std::string render_file;
  bool only_default = false;
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--plan" && i + 1 < argc) {
      a.plan_dir = argv[++i];
    } else if (s == "--out" && i + 1 < argc) {
      a.out = argv[++i];
    } else if (s == "--render" && i + 1 < argc) {
      a.render_file = argv[++i];
    } else if (s == "--only-default") {
      a.only_default = true;
    } else {
      return false;
    }
  }
  return !a.plan_dir.empty() && !a.out.empty();
}

// The entries of the plan grouped by the file they come from, in the plan's order.
std::vector<std::vector<PlanEntry>> by_source(const std::vector<PlanEntry>& plan) {
  std::vector<std::vector<PlanEntry>> out;
  std::map<std::string, std::size_t> index;
  for (const PlanEntry& e : plan) {
    if (!index.count(e.source)) {
      index[e.source] = out.size();
      out.emplace_back();
    }
    out[index[e.source]].push_back(e);
  }
  return out;
}

// How many of the source's frames its entries use (0: all).
int frames_needed(const std::vector<PlanEntry>& entries) {
  int most = 0;
  for (const PlanEntry& e : entries) {
    if (e.frames <= 0) return 0;
    most = std::max(most, e.start + e.frames * e.step);
  }
  return most;
}

// The entry's clip, its starts and buffers; null when its frames are not the truth's.
std::unique_ptr<Clip> build(const Clip& source, const PlanEntry& e, const Args& a,
                            const std::map<std::string, Starts>& starts) {
  auto c = make_entry(source, e);
  if (starts.count(e.entry)) c->starts = starts.at(e.entry);
  if (e.variant.empty() && !same_frames(*c, a.plan_dir + "/truth/" + e.entry + ".csv")) {
    std::fprintf(stderr, "projtrack-real: the truth of %s does not match the frames of %s\n",
                 e.entry.c_str(), e.source.c_str());
    return nullptr;
  }
  make_buffers(*c);
  return c;
}

int run(const Args& a) {
  const std::vector<PlanEntry> plan = read_plan(a.plan_dir);
  const auto starts = read_starts(a.plan_dir);
  std::vector<RenderRequest> requests;
  if (!a.render_file.empty()) requests = read_render_requests(a.render_file);
  std::set<std::string> wanted;
  for (const RenderRequest& r : requests) wanted.insert(r.entry);
  std::filesystem::create_directories(a.out);
  std::unique_ptr<RunsCsv> runs;
  std::FILE* speed = nullptr;
  long steps = 0;
  for (const PlanEntry& e : plan) steps += e.frames > 0 ? e.frames : 300;
  if (a.render_file.empty()) {
    runs = std::make_unique<RunsCsv>(a.out + "/runs.csv");
    speed = std::fopen((a.out + "/speed.csv").c_str(), "w");
    if (!runs->ok() || !speed) return std::fprintf(stderr, "projtrack-real: cannot write\n"), 1;
    std::fprintf(speed, "clip,resolution,what,median_us,frames\n");
  }
  std::vector<std::unique_ptr<Clip>> done;  // their frames released: for meta.json
  Progress progress(steps);
  for (const auto& entries : by_source(plan)) {
    Clip source;
    source.path = entries[0].source;
    bool any = wanted.empty();
    for (const PlanEntry& e : entries) any = any || wanted.count(e.entry);
    if (!any) continue;
    if (!decode(source.path, entries[0].kind, source, frames_needed(entries))) {
      std::fprintf(stderr, "projtrack-real: cannot decode %s\n", source.path.c_str());
      return 1;
    }
    for (const PlanEntry& e : entries) {
      if (!wanted.empty() && !wanted.count(e.entry)) continue;
      std::unique_ptr<Clip> c = build(source, e, a, starts);
      if (!c) return 1;
      for (const RenderRequest& r : requests)
        if (r.entry == e.entry) render(*c, r, a.out + "/frames");
      if (runs) {
        run_all(*c, *runs, progress, a.only_default);
        if (c->variant.empty() && c->has_truth()) speed_1080p(*c, speed, progress);
      }
      c->release_frames();  // a done clip kept only for meta.json: its frames and buffers freed
      done.push_back(std::move(c));
    }
  }
  if (speed) std::fclose(speed);
  runs.reset();
  if (a.render_file.empty()) write_meta(a.out, done);
  return 0;
}

}  // namespace
}  // namespace projtrack::bench

int main(int argc, char** argv) {
  using namespace projtrack::bench;
  gst_init(&argc, &argv);
  Args a;
  if (!parse(argc, argv, a)) {
    std::fprintf(stderr,
                 "usage: projtrack-real --plan DIR --out DIR [--only-default] [--render FILE]\n");
    return 2;
  }
  if (GstElementFactory* f = gst_element_factory_find("projtrack")) {
    gst_object_unref(f);
  } else {
    std::fprintf(stderr, "projtrack-real: the projtrack element is not found (GST_PLUGIN_PATH)\n");
    return 1;
  }
  cv::setNumThreads(1);  // one thread for every tracker (cvtracker's OpenCV included)
  const int status = run(a);
  gst_deinit();
  return status;
}
