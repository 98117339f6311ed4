// What a unit of work (include/projtrack/work_budget.hpp) costs in time, method by method, beside
// what a pixel visited (Features::pixels_visited) costs: the check of the budget's weights. Every
// estimator runs on the adversarial set at 1920×1080 (synthetic/adversarial.hpp: each frame read as
// an edge map, and its Canny edges), from the frame's centre and from a point off it, with its
// default parameters and with heavy ones (more rays, a finer grid); Canny runs on every frame too.
// Each case is timed 3 times, the least kept; only cases of at least 200 000 units count, where
// fixed costs do not matter. The weights are right when every method's nanoseconds per unit lie
// within a few times of each other, where its nanoseconds per pixel visited need not. Built with
// the tools option (tools/meson.build), in a build folder made by ./run build:
//
//   meson configure build -Dtools=enabled && meson compile -C build
//   build/tools/work_cost
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "adversarial.hpp"
#include "edges/canny.hpp"
#include "projtrack/edge_detection.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/work_budget.hpp"

namespace {

using namespace projtrack;
using Clock = std::chrono::steady_clock;

struct Range {
  double lo = 1e300, hi = 0;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return hi == 0; }
};

ImageView view(const cv::Mat& m) {
  return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
}

// The least of three runs of f(), ns.
template <class F>
double least_ns(F&& f) {
  double best = 1e300;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main() {
  constexpr int kW = 1920, kH = 1080;
  std::vector<cv::Mat> maps, frames;
  EdgeMap edges;
  for (const synthetic::AdversaryInfo& a : synthetic::kAdversaries) {
    frames.push_back(synthetic::adversarial_frame(a.kind, kW, kH, 0));
    maps.push_back(frames.back());
    const ImageView e = edges.detect(view(frames.back()), EdgeParams{});
    maps.push_back(cv::Mat(kH, kW, CV_8U, const_cast<std::uint8_t*>(e.data), e.stride).clone());
  }
  Params heavy;
  heavy.rays = 64;
  heavy.recursion = 3;
  heavy.grid_size = 2;
  heavy.block_size = 1;
  EstimateOptions options;
  options.area_limit = 0.5 * kW * kH;  // as the tracker's fills stop
  std::printf("%-24s %-22s %-22s\n", "", "ns per unit", "ns per pixel visited");
  Range all;
  for (const MethodInfo& m : kMethods) {
    auto est = m.make();
    Range per_unit, per_pixel;
    for (const cv::Mat& map : maps) {
      for (const Params& p : {Params{}, heavy}) {
        for (Point2i seed : {Point2i{kW / 2, kH / 2}, Point2i{kW / 3, kH / 4}}) {
          WorkBudget budget;
          options.budget = &budget;
          Features f;
          const double ns = least_ns([&] {
            budget = WorkBudget();
            f = est->estimate(view(map), seed, p, options);
          });
          if (budget.spent() < 200000) continue;
          per_unit.add(ns / static_cast<double>(budget.spent()));
          per_pixel.add(ns / static_cast<double>(f.pixels_visited + f.rays_cast));
        }
      }
    }
    if (per_unit.empty()) continue;
    all.add(per_unit.lo);
    all.add(per_unit.hi);
    std::printf("%-24s %6.2f – %-13.2f %6.2f – %-13.2f\n", m.nick, per_unit.lo, per_unit.hi,
                per_pixel.lo, per_pixel.hi);
  }
  Range canny;
  CannyDetector detector;
  for (const cv::Mat& f : frames) {
    cv::Mat blurred;
    cv::blur(f, blurred, {3, 3});
    WorkBudget budget;
    const double ns = least_ns([&] {
      budget = WorkBudget();
      detector.detect(view(blurred), EdgeParams{}.low, EdgeParams{}.high, &budget);
    });
    canny.add(ns / static_cast<double>(budget.spent()));
  }
  all.add(canny.lo);
  all.add(canny.hi);
  std::printf("%-24s %6.2f – %-13.2f\n", "Canny", canny.lo, canny.hi);
  std::printf("every case: %.2f – %.2f ns per unit (%.1f× apart)\n", all.lo, all.hi,
              all.hi / all.lo);
  return 0;
}
