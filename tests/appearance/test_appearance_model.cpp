// The appearance model: colours learned on the object score high, those around it low, and so do
// colours it has never seen; close colours of different chroma stay apart.
#include <gtest/gtest.h>

#include <vector>

#include "appearance/appearance_model.hpp"

namespace projtrack {
namespace {

// A 40×20 planar YUV 4:4:4 image: left half colour a, right half colour b.
struct TwoColours {
  std::vector<std::uint8_t> y, u, v;
  ColorView view;
  TwoColours(const std::uint8_t a[3], const std::uint8_t b[3]) : y(800), u(800), v(800) {
    for (int i = 0; i < 800; ++i) {
      const std::uint8_t* c = i % 40 < 20 ? a : b;
      y[i] = c[0];
      u[i] = c[1];
      v[i] = c[2];
    }
    view.luma = ImageView(y.data(), 40, 20, 40);
    view.chroma = {u.data(), v.data(), 40, 1, 0, 0};
  }
};

Mask half(bool left) {
  Mask m;
  m.reset({0, 0, 40, 20});
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) m.row(y)[x] = (x < 20) == left;
  return m;
}

TEST(AppearanceModel, ObjectColoursHighSurroundingsLowUnseenLow) {
  // A dark neutral object held by a dark reddish hand: 10 levels of Cr apart.
  const std::uint8_t object[3] = {30, 128, 128}, hand[3] = {40, 120, 140};
  const TwoColours image(object, hand);
  AppearanceModel m;
  EXPECT_TRUE(m.empty());
  m.learn(image.view, {0, 0}, half(true), half(false), 1.0);
  EXPECT_FALSE(m.empty());
  EXPECT_GE(m.likelihood(30, 128, 128), 200);
  EXPECT_LE(m.likelihood(40, 120, 140), 50);
  EXPECT_LE(m.likelihood(220, 60, 200), 10) << "a colour never seen is no evidence of the object";
  std::vector<std::uint8_t> like, around;
  m.likelihood(image.view, {0, 0}, {0, 0, 40, 20}, like);
  m.surroundings_like(image.view, {0, 0}, {0, 0, 40, 20}, around);
  EXPECT_GE(like[5], 200);
  EXPECT_LE(like[35], 50);
  EXPECT_EQ(around[5], 0);
  EXPECT_EQ(around[35], 1);
}

TEST(AppearanceModel, LearningAtASmallRateMovesSlowly) {
  const std::uint8_t a[3] = {100, 100, 100}, b[3] = {200, 150, 150};
  const TwoColours image(a, b);
  AppearanceModel m;
  m.learn(image.view, {0, 0}, half(true), half(false), 1.0);
  const int before = m.likelihood(200, 150, 150);
  // The roles swap, at 5 %: b is still mostly surroundings.
  m.learn(image.view, {0, 0}, half(false), half(true), 0.05);
  EXPECT_GT(m.likelihood(200, 150, 150), before);
  EXPECT_LT(m.likelihood(200, 150, 150), 128);
}

TEST(AppearanceModel, GrayFramesUseLumaAlone) {
  std::vector<std::uint8_t> y(800);
  for (int i = 0; i < 800; ++i) y[i] = i % 40 < 20 ? 60 : 180;
  ColorView gray;
  gray.luma = ImageView(y.data(), 40, 20, 40);
  AppearanceModel m;
  m.learn(gray, {0, 0}, half(true), half(false), 1.0);
  std::vector<std::uint8_t> like;
  m.likelihood(gray, {0, 0}, {0, 0, 40, 20}, like);
  EXPECT_GE(like[0], 200);
  EXPECT_LE(like[39], 50);
}

TEST(AppearanceModel, RegionsOutsideTheImageScoreZero) {
  const std::uint8_t a[3] = {100, 100, 100}, b[3] = {200, 150, 150};
  const TwoColours image(a, b);
  AppearanceModel m;
  m.learn(image.view, {10, 10}, half(true), half(false), 1.0);  // masks offset from the image
  std::vector<std::uint8_t> like;
  m.likelihood(image.view, {0, 0}, {-5, -5, 10, 10}, like);
  ASSERT_EQ(like.size(), 100u);
  EXPECT_EQ(like[0], 0);  // outside the image
}

}  // namespace
}  // namespace projtrack
