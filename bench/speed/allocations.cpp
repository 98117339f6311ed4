// Section 5 of projtrack-speed: heap allocations per frame in steady state (the library alone,
// and the element less the harness around it), and the element's resident memory over a long run.
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "alloc_count.hpp"
#include "harness.hpp"
#include "output.hpp"
#include "projtrack/method.hpp"
#include "projtrack/names.hpp"
#include "projtrack/tracker.hpp"
#include "sections.hpp"

namespace projtrack::bench {
namespace {

long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

}  // namespace

void allocations_and_memory(Clip& clip, int frames) {
  constexpr int kCounted = 200;  // frames whose allocations are counted, after warm-up
  const int mark = std::min(1000, frames / 2);  // memory is compared from here to the last frame
  const std::size_t n = clip.gray.size();
  // The library alone, with the default model and with the edges model (which allocates nothing
  // of its own: the default's count is OpenCV's calls within it as much as ours).
  for (ObjectModelKind model : {TrackerParams{}.model, ObjectModelKind::Edges}) {
    const std::string suffix =
        model == TrackerParams{}.model ? "" : std::string(" (") + nick_of(model) + " model)";
    for (Method method : kAllMethods) {
      Tracker t;
      TrackerParams tp;
      tp.acquisition = Acquisition::Manual;
      tp.model = model;
      t.seed(clip.seeds[0]);
      auto frame = [&](std::size_t i) {
        const cv::Mat& g = clip.gray[i % n];
        t.track(ImageView(g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step)),
                EdgeParams{}, static_cast<double>(i) / 30, method, Params{}, tp);
      };
      for (std::size_t i = 0; i < 2 * n; ++i) frame(i);  // buffers grow to the largest region
      const long before = allocations.load();
      for (std::size_t i = 2 * n; i < 2 * n + kCounted; ++i) frame(i);
      row("allocations", &clip, "Tracker::track " + std::string(method_name(method)) + suffix,
          "per_frame", static_cast<double>(allocations.load() - before) / kCounted);
    }
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

}  // namespace projtrack::bench
