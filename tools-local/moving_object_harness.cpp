// Runs MovingObjectFinder on a clip from its first frame: per frame whether it found an object,
// the silhouette's centroid and area (input pixels), the time of find() and the work it charged;
// found silhouettes are written as PNGs for the judge (tools-local/judge.py).
// Usage: moving_object_harness <video | pgm glob> <out dir> [--scale-to WxH] [--threads N]
#include <dlfcn.h>
#include <glob.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "acquisition/moving_object.hpp"

// Heap allocations, counted while `counting` is set.
static std::atomic<long> g_allocs{0};
static std::atomic<bool> g_counting{false};
extern "C" void* __libc_malloc(size_t);
extern "C" void* malloc(size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocs.fetch_add(1);
  return __libc_malloc(n);
}

int main(int argc, char** argv) {
  if (argc < 3) return 2;
  const std::string src = argv[1], out = argv[2];
  cv::Size to;
  int threads = 1;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--scale-to")
      std::sscanf(argv[i + 1], "%dx%d", &to.width, &to.height);
    if (std::string(argv[i]) == "--threads") threads = std::atoi(argv[i + 1]);
  }
  cv::setNumThreads(threads);
  std::vector<std::string> files;
  cv::VideoCapture cap;
  if (src.find('*') != std::string::npos) {
    glob_t g;
    ::glob(src.c_str(), 0, nullptr, &g);
    for (size_t i = 0; i < g.gl_pathc; ++i) files.push_back(g.gl_pathv[i]);
    globfree(&g);
  } else {
    cap.open(src);
  }
  projtrack::MovingObjectFinder::Params params;
  // Overrides for tuning runs: MO_<NAME>=value.
  if (const char* v = std::getenv("MO_FRAMES")) params.frames = std::atoi(v);
  if (const char* v = std::getenv("MO_COMPACT")) params.least_compactness = std::atof(v);
  if (const char* v = std::getenv("MO_NOISE")) params.noise_spreads = std::atof(v);
  if (const char* v = std::getenv("MO_GROUP")) params.group_share = std::atof(v);
  if (const char* v = std::getenv("MO_DENSITY")) params.least_density = std::atof(v);
  if (const char* v = std::getenv("MO_LEAST")) params.least_share = std::atof(v);
  projtrack::MovingObjectFinder finder(params);
  cv::Mat frame, gray, input, work, sil;
  std::string why;
  std::printf("frame,found,cx,cy,area,find_us,resize_us,units,allocs,why\n");
  for (int f = 0;; ++f) {
    if (!files.empty()) {
      if (f >= static_cast<int>(files.size())) break;
      frame = cv::imread(files[f], cv::IMREAD_GRAYSCALE);
    } else if (!cap.read(frame)) {
      break;
    }
    if (frame.channels() == 3)
      cv::cvtColor(frame, gray, cv::COLOR_BGR2GRAY);
    else
      gray = frame;
    if (to.area() > 0)
      cv::resize(gray, input, to, 0, 0, cv::INTER_LINEAR);
    else
      input = gray;
    // The caller's working scale: ~100k px, never above the input's.
    const double s = std::min(1.0, std::sqrt(100000.0 / input.total()));
    const auto t0 = std::chrono::steady_clock::now();
    if (s < 1)
      cv::resize(input, work,
                 cv::Size(static_cast<int>(std::lround(input.cols * s)),
                          static_cast<int>(std::lround(input.rows * s))),
                 0, 0, cv::INTER_AREA);
    else
      work = input;
    const auto t1 = std::chrono::steady_clock::now();
    projtrack::WorkBudget budget;
    g_allocs = 0;
    g_counting = true;
    const bool found = finder.find(work, budget, sil, why);
    g_counting = false;
    const auto t2 = std::chrono::steady_clock::now();
    double cx = 0, cy = 0, area = 0;
    if (found) {
      const cv::Moments m = cv::moments(sil, true);
      const double k = static_cast<double>(input.cols) / work.cols;
      area = m.m00 * k * k;
      cx = ((m.m10 / m.m00) + 0.5) * k - 0.5;
      cy = ((m.m01 / m.m00) + 0.5) * k - 0.5;
      char name[64];
      std::snprintf(name, sizeof name, "/%05d.png", f);
      cv::imwrite(out + name, sil);
    }
    std::printf("%d,%d,%.1f,%.1f,%.0f,%.0f,%.0f,%llu,%ld,\"%s\"\n", f, found ? 1 : 0, cx, cy, area,
                std::chrono::duration<double, std::micro>(t2 - t1).count(),
                std::chrono::duration<double, std::micro>(t1 - t0).count(),
                static_cast<unsigned long long>(budget.spent()), g_allocs.load(), why.c_str());
  }
  return 0;
}
