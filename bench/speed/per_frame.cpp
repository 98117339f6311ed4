// Sections 1–3 of projtrack-speed: every method in the element against a frame copy and the
// peers, per frame, on one clip.
#include <algorithm>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "harness.hpp"
#include "method_list.hpp"
#include "output.hpp"
#include "peers.hpp"
#include "projtrack/method.hpp"
#include "projtrack/tracker.hpp"
#include "race.hpp"
#include "sections.hpp"

namespace projtrack::bench {

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
  // stock-OpenCV peer's too), and the element as users run it (the default flow model).
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

}  // namespace projtrack::bench
