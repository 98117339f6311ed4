// handwritten_cost: every routine written by hand in src/ (and the overlay's font in gst/) that
// OpenCV also provides, against the library call, side by side in one run: time and heap
// allocations per call on realistic inputs (a real frame at 640×480 and 1920×1080, the hand's
// mask at the scales the project works at), each side into buffers made once, as a stream calls
// them. Its CSV is the table of docs/architecture.md ("Written by hand"), which
// tools/handwritten_table.py writes: the numbers are never typed. Built with the tools option:
//
//   meson configure build -Dtools=enabled && meson compile -C build
//   build/tools/handwritten_cost [--quick] [--clip FILE] > docs/architecture/handwritten.csv
//   tools/handwritten_table.py docs/architecture/handwritten.csv docs/architecture.md
//
// A tool rather than a section of projtrack-speed: it runs in a minute on its own (the speed
// bench takes most of an hour), and its rows are no target of docs/performance.md.
#include <gst/gst.h>

#include <cstdio>
#include <opencv2/core/utility.hpp>
#include <string>

#include "cases.hpp"

int main(int argc, char** argv) {
  using namespace projtrack::handwritten;
  std::string clip = "/usr/share/doc/opencv-doc/examples/data/Megamind.avi";
  Effort effort;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      effort = {3, 3};
    } else if (a == "--clip" && i + 1 < argc) {
      clip = argv[++i];
    } else {
      std::fprintf(stderr, "usage: handwritten_cost [--quick] [--clip FILE] > FILE.csv\n");
      return 2;
    }
  }
  gst_init(&argc, &argv);
  cv::setNumThreads(1);  // as the speed bench: one thread for the library as for ours
  // Frame 100: the character in the middle of a busy background.
  const std::vector<Frame> frames = {real_frame(clip, 100, 640, 480),
                                     real_frame(clip, 100, 1920, 1080)};
  write_header(stdout);
  pixel_duels(frames, effort, stdout);
  mask_duels(hand_masks(), effort, stdout);
  text_duels(frames, effort, stdout);
  return 0;
}
