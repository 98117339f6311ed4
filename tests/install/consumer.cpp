// An application built against the installed library, as a user builds one:
//   c++ -std=c++17 consumer.cpp $(pkg-config --cflags --libs projtrack)
// It tracks a drawn disc moving right with the library's Tracker and measures it with one
// estimator, and fails (exit 1) unless both find it where it is.
#include <cmath>
#include <cstdio>
#include <projtrack/projtrack.hpp>
#include <vector>

int main() {
  const int w = 320, h = 240, r = 40;
  std::vector<unsigned char> frame(static_cast<size_t>(w) * h);
  const auto draw = [&](int cx, int cy) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) frame[y * w + x] = std::hypot(x - cx, y - cy) <= r ? 220 : 40;
  };
  const projtrack::ImageView gray(frame.data(), w, h, w);

  draw(160, 120);
  projtrack::EdgeMap edge_map;
  auto estimator = projtrack::make_estimator(projtrack::Method::GridFilling);
  const projtrack::Features f = estimator->estimate(edge_map.detect(gray, {}), {160, 120}, {});
  std::printf("estimator: %s centroid %.1f,%.1f area %.0f\n",
              projtrack::status_name(f.status).data(), f.centroid.x, f.centroid.y, f.area);
  bool ok = f.valid() && std::hypot(f.centroid.x - 160, f.centroid.y - 120) < 2;

  projtrack::Tracker tracker;
  projtrack::TrackerParams defaults;
  defaults.push.threshold = 0.2;  // what an application tunes; TrackerParams copies as a value
  projtrack::TrackerParams tp = defaults;
  tracker.seed({160, 120});
  for (int i = 0; i < 10; ++i) {
    const int cx = 160 + 3 * i;
    draw(cx, 120);
    const projtrack::TrackResult t = tracker.track(gray, projtrack::EdgeParams{}, i / 30.0,
                                                   projtrack::Method::GapTolerantFilling, {}, tp);
    std::printf("frame %d: %s centroid %.1f depth %.2f\n", i,
                projtrack::status_name(t.status).data(), t.features.centroid.x, t.pose.depth);
    ok = ok && projtrack::has_features(t.status) && std::abs(t.features.centroid.x - cx) < 2;
  }
  std::printf(ok ? "consumer: ok\n" : "consumer: FAILED\n");
  return ok ? 0 : 1;
}
