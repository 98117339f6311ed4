// Depth is one rule: √(area ÷ the frame's area). The same however the track started (a point, a
// box, acquisition), at any resolution, and continuous through a loss and a re-acquisition: no
// reference is reset, so it changes only as the object's size does.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "projtrack/tracker.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

// A bright disc (radius 0: none) in the middle of a dark frame, and its edges.
using Frame = test::GrayFrame;
Frame disc(int r, int w = 320, int h = 240) { return test::disc_frame(w / 2, h / 2, r, w, h); }

TrackerParams edges_model(Acquisition a) {
  TrackerParams tp;
  tp.model = ObjectModelKind::Edges;
  tp.acquisition = a;
  tp.smoothing = false;
  return tp;
}

double share_depth(const TrackResult& r, int w, int h) {
  return std::sqrt(r.features.area / (static_cast<double>(w) * h));
}

TEST(Depth, IsTheObjectsSideAsAShareOfTheFramesAtAnyResolution) {
  const TrackerParams tp = edges_model(Acquisition::Center);
  Tracker small, large;
  const TrackResult a = small.track(disc(40).g(), disc(40).e(), 0, Method::PixelFilling, {}, tp);
  const Frame big = disc(80, 640, 480);
  const TrackResult b = large.track(big.g(), big.e(), 0, Method::PixelFilling, {}, tp);
  ASSERT_TRUE(has_features(a.status) && has_features(b.status));
  EXPECT_DOUBLE_EQ(a.raw_pose.depth, share_depth(a, 320, 240));
  EXPECT_NEAR(a.raw_pose.depth, std::sqrt(M_PI * 40 * 40 / (320 * 240)), 0.01);
  EXPECT_NEAR(b.raw_pose.depth, a.raw_pose.depth, 0.01 * a.raw_pose.depth);
}

// The same object, nearing the camera (radius 40 to 59 px over 20 frames), followed by tracks
// started in different ways and at different moments: on the last frame they all read the same
// depth, its size's (a depth relative to each track's first area would read 1.5, 1.2 and 1).
TEST(Depth, TheSameHoweverAndWheneverTheTrackStarted) {
  struct Start {
    const char* what;
    int frame;
    std::function<void(Tracker&)> start;
    Acquisition acquisition;
  };
  const std::vector<Start> starts = {
      {"a point, frame 0", 0,
       [](Tracker& t) {
         t.seed({170, 110});
       },
       Acquisition::Manual},
      {"a box, frame 0", 0,
       [](Tracker& t) {
         t.seed_box({110, 70, 100, 100});
       },
       Acquisition::Manual},
      {"a point, frame 10", 10,
       [](Tracker& t) {
         t.seed({150, 130});
       },
       Acquisition::Manual},
      {"the frame's centre, frame 19", 19, [](Tracker&) {}, Acquisition::Center},
  };
  std::vector<double> last;
  for (const Start& s : starts) {
    Tracker t;
    const TrackerParams tp = edges_model(s.acquisition);
    TrackResult r;
    for (int i = s.frame; i < 20; ++i) {
      if (i == s.frame) s.start(t);
      const Frame f = disc(40 + i);
      r = t.track(f.g(), f.e(), i / 30.0, Method::PixelFilling, {}, tp);
      if (i == s.frame) {
        EXPECT_TRUE(r.acquired) << s.what;
      }
    }
    ASSERT_TRUE(has_features(r.status)) << s.what << ": " << r.detail;
    EXPECT_DOUBLE_EQ(r.raw_pose.depth, share_depth(r, 320, 240)) << s.what;
    last.push_back(r.raw_pose.depth);
  }
  for (std::size_t i = 1; i < last.size(); ++i)
    EXPECT_NEAR(last[i], last[0], 0.005 * last[0]) << starts[i].what;
  EXPECT_NEAR(last[0], std::sqrt(M_PI * 59 * 59 / (320 * 240)), 0.02);
}

// The disc for 10 frames, nothing for 10 (the track is dropped), the disc of radius `back` again.
struct Reacquired {
  double before = 0, after = 0;
  int acquisitions = 0, refused = 0;
};

Reacquired through_a_loss(int back) {
  const TrackerParams tp = edges_model(Acquisition::Center);
  Tracker t;
  Reacquired out;
  for (int i = 0; i < 30; ++i) {
    const Frame f = disc(i < 10 ? 40 : i < 20 ? 0 : back);
    const TrackResult r = t.track(f.g(), f.e(), i / 30.0, Method::PixelFilling, {}, tp);
    out.acquisitions += r.acquired;
    out.refused += !has_features(r.status);
    if (i == 9) out.before = r.pose.depth;
    if (i == 20) out.after = r.pose.depth;
  }
  return out;
}

TEST(Depth, GoesOnThroughALossAndAReacquisition) {
  const Reacquired same = through_a_loss(40);
  EXPECT_EQ(same.acquisitions, 2);  // dropped while away, acquired again on its return
  EXPECT_EQ(same.refused, 10);
  EXPECT_NEAR(same.after, same.before, 0.01 * same.before);  // no jump: nothing was reset
  // Back nearer the camera: depth follows the object's size, 50 / 40.
  const Reacquired nearer = through_a_loss(50);
  EXPECT_EQ(nearer.acquisitions, 2);
  EXPECT_NEAR(nearer.after / nearer.before, 1.25, 0.03);
}

}  // namespace
}  // namespace projtrack
