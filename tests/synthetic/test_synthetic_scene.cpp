// The synthetic scenes (the benchmark's and the sequence tests'): exact truth, the edge
// miscalculations asked for, seeds inside.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>

#include "projtrack/estimator.hpp"
#include "scene.hpp"

namespace projtrack::synthetic {
namespace {

TEST(SyntheticScene, TruthAgreesWithIndependentCountsAtBothResolutions) {
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}}) {
    for (Object o : {Object::Sphere, Object::Hand}) {
      const Scene s = make_scene({w, h, o, 0, false, 0}, EdgeParams{});
      std::string why;
      EXPECT_TRUE(truth_is_consistent(s, &why)) << object_name(o) << ' ' << w << ": " << why;
      EXPECT_EQ(s.true_area, cv::countNonZero(s.mask));
      const cv::Moments m = cv::moments(s.mask, true);
      EXPECT_NEAR(s.true_centroid.x, m.m10 / m.m00, 1e-6);
      EXPECT_NEAR(s.true_centroid.y, m.m01 / m.m00, 1e-6);
      // About a tenth of the frame or less, as the element's speed targets assume.
      EXPECT_LT(s.true_area, 0.1 * w * h);
      EXPECT_GT(s.true_area, 0.03 * w * h);
    }
  }
}

// Without deliberate gaps, the edges close the object: a fill from inside stays inside.
TEST(SyntheticScene, ClosedContoursAreClosed) {
  auto fill = make_estimator(Method::PixelFilling);
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}})
    for (Object o : {Object::Sphere, Object::Hand})
      for (int instance : {0, 1}) {
        const Scene s = make_scene({w, h, o, 0, false, instance}, EdgeParams{});
        EXPECT_LE(s.natural_gaps, 0.01 * s.contour_pixels);
        std::mt19937 rng(9);
        for (const Seed& seed : sample_seeds(s, 12, rng)) {
          const Features f = fill->estimate(s.edge_view(), seed.p, {});
          EXPECT_EQ(f.status, EstimateStatus::Ok) << object_name(o) << ' ' << w << ' ' << seed.part;
          EXPECT_NEAR(f.area / s.true_area, 0.97, 0.03) << object_name(o) << ' ' << w;
        }
      }
}

TEST(SyntheticScene, GapsRemoveTheRequestedShareOfTheContour) {
  for (double rate : {0.01, 0.05, 0.10}) {
    const Scene s = make_scene({640, 480, Object::Hand, rate, false, 0}, EdgeParams{});
    EXPECT_NEAR(s.gap_pixels_removed, rate * s.contour_pixels, 2.0) << rate;
    const Scene closed = make_scene({640, 480, Object::Hand, 0, false, 0}, EdgeParams{});
    EXPECT_EQ(closed.gap_pixels_removed, 0);
  }
}

TEST(SyntheticScene, SpuriousEdgesLandInsideTheObject) {
  const Scene s = make_scene({640, 480, Object::Sphere, 0, true, 0}, EdgeParams{});
  EXPECT_GT(s.spurious_pixels, 50);
  EXPECT_EQ(make_scene({640, 480, Object::Sphere, 0, false, 0}, EdgeParams{}).spurious_pixels, 0);
}

TEST(SyntheticScene, SeedsCoverEveryPartOfTheHandAndLieInside) {
  const Scene s = make_scene({640, 480, Object::Hand, 0, false, 0}, EdgeParams{});
  std::mt19937 rng(5);
  const std::vector<Seed> seeds = sample_seeds(s, 24, rng);
  std::set<std::string> parts;
  for (const Seed& seed : seeds) {
    parts.insert(seed.part);
    EXPECT_NE(s.mask.at<std::uint8_t>(seed.p.y, seed.p.x), 0) << seed.part;
  }
  EXPECT_EQ(parts.size(), 6u);  // palm, four fingers, thumb
  EXPECT_EQ(seeds.size(), 24u);
}

}  // namespace
}  // namespace projtrack::synthetic
