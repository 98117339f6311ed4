// The finder's scene background (learned while acquisition searches) and frames of another size:
// after a rescale a tracked frame is judged against the background (still or moving), which was
// learned at the old size and is none of the new frames'.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <string>

#include "acquisition/object_finder.hpp"

namespace projtrack {
namespace {

// A gray w × h frame: its left half 100, its right half 200.
cv::Mat halves(int w, int h) {
  cv::Mat m(h, w, CV_8U, cv::Scalar(100));
  m(cv::Rect(w / 2, 0, w - w / 2, h)).setTo(200);
  return m;
}

ColorView view(const cv::Mat& m) {
  return {ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step)), {}, {}};
}

// A square silhouette of frame pixels (scale 1).
Mask square(int x, int y, int side) {
  Mask s;
  s.reset({x, y, side, side});
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) s.row(r)[c] = 1;
  return s;
}

// The finder's background learned on 320×240 frames of `halves`.
void learn_background(ObjectFinder& finder, const FinderParams& p) {
  const cv::Mat frame = halves(320, 240);
  Mask out;
  Point2i seed;
  std::string why;
  for (int i = 0; i <= p.background_frames; ++i)
    finder.from_motion(view(frame), {}, {}, p, out, seed, why);
}

TEST(ObjectFinder, TheBackgroundOfFramesOfAnotherSizeIsNotRead) {
  const FinderParams p;
  ObjectFinder finder;
  learn_background(finder, p);
  const cv::Mat same = halves(320, 240);
  EXPECT_EQ(finder.foreground_share(view(same), square(200, 40, 40), 1, p), 0.0)
      << "on frames of its size, the background is known";
  // The same scene at half the size: read with the small frames' rows, the background compared
  // every second row with pixels of the other half (a share near 0.5, neither background nor
  // not). Unknown for these frames: every pixel counts, as before a background is learned.
  const cv::Mat half = halves(160, 120);
  EXPECT_EQ(finder.foreground_share(view(half), square(100, 10, 30), 1, p), 1.0);
  // 1280×720: a work frame of 427×240 (the finder's scale 3), read with its rows past the end of
  // the background's 320×240.
  const cv::Mat wide = halves(1280, 720);
  EXPECT_EQ(finder.foreground_share(view(wide), square(1100, 600, 60), 1, p), 1.0);
  // 960×720 at the finder's scale 3 is a work frame of the background's own layout: known.
  const cv::Mat large = halves(960, 720);
  EXPECT_EQ(finder.foreground_share(view(large), square(800, 600, 60), 1, p), 0.0);
}

}  // namespace
}  // namespace projtrack
