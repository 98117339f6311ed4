// Sections 7–8 of projtrack-speed: bounded work (issue 16; section 9 is interrupt.cpp). Every
// frame is timed alone; a configuration runs its sequence `reps` times in the same element (the
// track reset between runs), and a frame's time is its least over the runs: what the frame costs,
// without the machine's noise (other processes on the shared cores only ever add). The worst frame
// is the largest of those; an ordinary frame the median of the same on the generated clip.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "harness.hpp"
#include "method_list.hpp"
#include "output.hpp"
#include "projtrack/method.hpp"
#include "race.hpp"
#include "sections.hpp"

namespace projtrack::bench {
namespace {

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

void status_rows(const std::string& section, const Clip& c, const std::string& what,
                 const FrameTimes& t) {
  for (const auto& [status, n] : t.statuses)
    row(section, &c, what, "status_" + (status.empty() ? std::string("none") : status), n);
}

}  // namespace

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

}  // namespace projtrack::bench
