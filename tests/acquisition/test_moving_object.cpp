// MovingObjectFinder on generated scenes: an object moving apart from the picture's motion is
// found (static or panned background), and nothing else is: a pan alone, noise, a flat frame, a
// flash, a flickering static patch, an arm reaching in from the border.
#include <gtest/gtest.h>

#include <atomic>
#include <opencv2/imgproc.hpp>
#include <string>

#include "acquisition/moving_object.hpp"

namespace projtrack {
namespace {

constexpr int kW = 320, kH = 240;

// A smooth random texture (blurred noise, contrast stretched), the same for a given seed.
cv::Mat texture(int w, int h, std::uint64_t seed, double blur = 2.0) {
  cv::Mat noise(h, w, CV_8U);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, cv::Size(), blur);
  cv::normalize(noise, noise, 40, 220, cv::NORM_MINMAX);
  return noise;
}

// The background (a window of `scene` at `offset`) with a textured disc of radius `r` at `c`.
cv::Mat frame_with_disc(const cv::Mat& scene, cv::Point offset, cv::Point c, int r,
                        const cv::Mat& disc_texture) {
  cv::Mat f = scene(cv::Rect(offset, cv::Size(kW, kH))).clone();
  cv::Mat mask(kH, kW, CV_8U, cv::Scalar(0));
  cv::circle(mask, c, r, cv::Scalar(255), cv::FILLED);
  disc_texture.copyTo(f, mask);
  return f;
}

struct Found {
  int frame = -1;  // the first frame found on, -1 for none
  cv::Mat silhouette;
};

// The disc scene: `frames` frames, the disc from (80, 120) moving by `step`, the background's
// window moving by `pan` a frame.
Found run_disc(MovingObjectFinder& finder, int frames, cv::Point step, cv::Point pan) {
  const cv::Mat scene = texture(kW + 100, kH + 100, 7);
  const cv::Mat disc = texture(kW, kH, 11, 1.0);
  Found found;
  for (int i = 0; i < frames; ++i) {
    const cv::Point offset(20 + pan.x * i, 20 + pan.y * i);
    const cv::Mat f = frame_with_disc(scene, offset, cv::Point(80, 120) + step * i, 20, disc);
    WorkBudget budget;
    cv::Mat sil;
    std::string why;
    if (finder.find(f, budget, sil, why) && found.frame < 0) {
      found.frame = i;
      found.silhouette = sil;
    }
  }
  return found;
}

// Whether `sil` is the disc of radius `r` at `c`: centroid within r/2, area within 1/2-2x.
void expect_disc(const cv::Mat& sil, cv::Point2d c, int r) {
  ASSERT_FALSE(sil.empty());
  const cv::Moments m = cv::moments(sil, true);
  ASSERT_GT(m.m00, 0);
  const cv::Point2d centre(m.m10 / m.m00, m.m01 / m.m00);
  EXPECT_LE(cv::norm(centre - c), r / 2.0) << centre;
  const double area = CV_PI * r * r;
  EXPECT_GE(m.m00, area / 2);
  EXPECT_LE(m.m00, area * 2);
}

// Runs `frames` of `make(i)` and returns how many were found.
template <class Make>
int finds(MovingObjectFinder& finder, int frames, Make&& make, std::string* last_why = nullptr) {
  int n = 0;
  for (int i = 0; i < frames; ++i) {
    WorkBudget budget;
    cv::Mat sil;
    std::string why;
    n += finder.find(make(i), budget, sil, why);
    if (last_why) *last_why = why;
  }
  return n;
}

TEST(MovingObjectFinder, DiscMovingOverAStaticBackgroundIsFound) {
  MovingObjectFinder finder;
  const Found f = run_disc(finder, 12, {3, 1}, {0, 0});
  ASSERT_GE(f.frame, 0);
  EXPECT_LE(f.frame, 5) << "three frames of motion after the two it needs to compare";
  expect_disc(f.silhouette, cv::Point2d(80 + 3 * f.frame, 120 + f.frame), 20);
}

TEST(MovingObjectFinder, DiscMovingAgainstAPanIsFoundNotTheBackground) {
  MovingObjectFinder finder;
  // The camera pans 3 px right and 2 down a frame (the picture moves left and up); the disc
  // moves right on the screen.
  const Found f = run_disc(finder, 14, {3, 0}, {3, 2});
  ASSERT_GE(f.frame, 0);
  EXPECT_LE(f.frame, 6);
  expect_disc(f.silhouette, cv::Point2d(80 + 3 * f.frame, 120), 20);
}

TEST(MovingObjectFinder, APanAloneIsNoObject) {
  MovingObjectFinder finder;
  const cv::Mat scene = texture(kW + 100, kH + 100, 7);
  std::string why;
  EXPECT_EQ(
      finds(
          finder, 20,
          [&](int i) { return scene(cv::Rect(cv::Point(10 + 4 * i, 10 + i), cv::Size(kW, kH))); },
          &why),
      0)
      << why;
}

TEST(MovingObjectFinder, NoiseIsNoObject) {
  MovingObjectFinder finder;
  cv::RNG rng(3);
  cv::Mat f(kH, kW, CV_8U);
  EXPECT_EQ(finds(finder, 20,
                  [&](int) {
                    rng.fill(f, cv::RNG::NORMAL, 128, 20);
                    return f;
                  }),
            0);
  // Noise added to every pixel of a textured still scene, fresh each frame.
  finder.reset();
  const cv::Mat scene = texture(kW, kH, 5);
  cv::Mat noise(kH, kW, CV_16S), sum, noisy;
  EXPECT_EQ(finds(finder, 20,
                  [&](int) {
                    rng.fill(noise, cv::RNG::NORMAL, 0, 12);
                    scene.convertTo(sum, CV_16S);
                    sum += noise;
                    sum.convertTo(noisy, CV_8U);
                    return noisy;
                  }),
            0);
}

TEST(MovingObjectFinder, AFlatFrameIsNoObjectAndCheap) {
  MovingObjectFinder flat_finder, textured_finder;
  const cv::Mat flat(kH, kW, CV_8U, cv::Scalar(90));
  const cv::Mat scene = texture(kW + 100, kH + 100, 7);
  std::uint64_t flat_cost = 0, textured_cost = 0;
  cv::Mat sil;
  std::string why;
  for (int i = 0; i < 6; ++i) {
    WorkBudget a, b;
    EXPECT_FALSE(flat_finder.find(flat, a, sil, why));
    textured_finder.find(scene(cv::Rect(cv::Point(10 + 2 * i, 10), cv::Size(kW, kH))), b, sil, why);
    flat_cost = a.spent();
    textured_cost = b.spent();
  }
  // No motion to measure on a flat frame: the optical flow is not run.
  EXPECT_LT(flat_cost, textured_cost / 2);
}

TEST(MovingObjectFinder, AFlashIsNoObject) {
  MovingObjectFinder finder;
  const cv::Mat scene = texture(kW, kH, 9);
  cv::Mat bright;
  cv::add(scene, cv::Scalar(40), bright);
  // Every third frame lit (a flash), and the light left on from frame 10.
  EXPECT_EQ(finds(finder, 20, [&](int i) { return (i % 3 == 2 || i >= 10) ? bright : scene; }), 0);
}

TEST(MovingObjectFinder, AFlickeringStaticPatchIsNoObject) {
  MovingObjectFinder finder;
  const cv::Mat scene = texture(kW, kH, 9);
  const cv::Rect patch(140, 90, 40, 40);
  std::string why;
  EXPECT_EQ(finds(
                finder, 16,
                [&](int i) {
                  cv::Mat f = scene.clone();
                  cv::Mat p = f(patch);
                  p.convertTo(p, -1, i % 2 ? 1.5 : 0.7, i % 2 ? 10 : -10);
                  return f;
                },
                &why),
            0)
      << why;
}

TEST(MovingObjectFinder, AnArmReachingInFromTheBorderIsNoObject) {
  MovingObjectFinder finder;
  const cv::Mat scene = texture(kW, kH, 13);
  const cv::Mat arm = texture(kW, kH, 17, 1.0);
  std::string why;
  EXPECT_EQ(finds(
                finder, 16,
                [&](int i) {
                  cv::Mat f = scene.clone();
                  const cv::Rect bar(0, 80 + 4 * (i % 6), 120 + 4 * i, 30);
                  arm(bar).copyTo(f(bar));
                  return f;
                },
                &why),
            0)
      << why;
}

TEST(MovingObjectFinder, SameFramesSameSilhouette) {
  MovingObjectFinder a, b;
  const Found fa = run_disc(a, 10, {3, 1}, {2, 1});
  b.reset();
  const Found fb = run_disc(b, 10, {3, 1}, {2, 1});
  ASSERT_EQ(fa.frame, fb.frame);
  ASSERT_GE(fa.frame, 0);
  EXPECT_EQ(cv::countNonZero(fa.silhouette != fb.silhouette), 0);
}

TEST(MovingObjectFinder, ABudgetSpentOrAStopEndsTheFrame) {
  MovingObjectFinder finder;
  const cv::Mat scene = texture(kW, kH, 9);
  cv::Mat sil;
  std::string why;
  WorkBudget none(0);
  EXPECT_FALSE(finder.find(scene, none, sil, why));
  EXPECT_NE(why.find("budget"), std::string::npos) << why;
  std::atomic<bool> stop{true};
  WorkBudget stopped(WorkBudget::kUnlimited, &stop);
  EXPECT_FALSE(finder.find(scene, stopped, sil, why));
  EXPECT_EQ(why, "stopped");
  // A budget that runs out after the frame's motion: the frame ends there.
  WorkBudget small(1000);
  EXPECT_FALSE(finder.find(scene, small, sil, why));
  EXPECT_LE(small.spent(), 2'000'000u);
}

TEST(MovingObjectFinder, ANewFrameSizeStartsAfresh) {
  MovingObjectFinder finder;
  run_disc(finder, 4, {3, 1}, {0, 0});
  const cv::Mat small = texture(100, 80, 3);
  cv::Mat sil;
  std::string why;
  WorkBudget budget;
  EXPECT_FALSE(finder.find(small, budget, sil, why));
  EXPECT_NE(why.find("1 of 3"), std::string::npos) << why;
}

}  // namespace
}  // namespace projtrack
