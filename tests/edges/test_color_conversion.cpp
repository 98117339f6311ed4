// Packed RGB to video-range luma and chroma; full range to video range; one component of a
// packed format gathered into a plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "projtrack/color_conversion.hpp"

namespace projtrack {
namespace {

TEST(GrayConversion, Bt601WeightsInEveryComponentOrderAndPixelSize) {
  // Two rows of red, green, blue, white, black, padded to 23 bytes per row.
  const std::uint8_t colours[5][3] = {
      {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {0, 0, 0}};
  // Video range: black 16, white 235 (BT.601's studio swing, as I420 stores them).
  const std::uint8_t expected[5] = {82, 144, 41, 235, 16};
  for (int pixel_stride : {3, 4}) {
    for (int r_off : {0, 1, 2}) {
      const int g_off = (r_off + 1) % 3, b_off = (r_off + 2) % 3;
      const int row_stride = 23;
      std::vector<std::uint8_t> rgb(row_stride * 2, 0xAB);
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 5; ++x) {
          std::uint8_t* p = &rgb[y * row_stride + x * pixel_stride];
          p[r_off] = colours[x][0];
          p[g_off] = colours[x][1];
          p[b_off] = colours[x][2];
        }
      std::vector<std::uint8_t> gray(2 * 7, 0xCD);
      packed_rgb_to_luma(&rgb[r_off], &rgb[g_off], &rgb[b_off], pixel_stride, row_stride, 5, 2,
                         gray.data(), 7);
      for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 5; ++x) EXPECT_EQ(gray[y * 7 + x], expected[x]) << pixel_stride;
        EXPECT_EQ(gray[y * 7 + 5], 0xCD);  // padding untouched
      }
    }
  }
}

TEST(GrayConversion, WideRowsGiveLumaOfEveryPixelInEveryLayout) {
  // Rows long enough for the vectorised path (16 pixels at a time) and a scalar tail, in a buffer
  // that ends with the last pixel (a read past it shows under AddressSanitizer): RGB, BGR, RGBx,
  // BGRx, xRGB and xBGR layouts.
  struct Layout {
    int stride, r, g, b;
  };
  const Layout layouts[] = {{3, 0, 1, 2}, {3, 2, 1, 0}, {4, 0, 1, 2},
                            {4, 2, 1, 0}, {4, 1, 2, 3}, {4, 3, 2, 1}};
  constexpr int kWidth = 71, kHeight = 3;
  for (const Layout& l : layouts) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(l.stride) * kWidth * kHeight);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>(i * 37 + i / 7);
    std::vector<std::uint8_t> luma(kWidth * kHeight);
    packed_rgb_to_luma(&rgb[l.r], &rgb[l.g], &rgb[l.b], l.stride, l.stride * kWidth, kWidth,
                       kHeight, luma.data(), kWidth);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const std::uint8_t* p = &rgb[(y * kWidth + x) * l.stride];
        ASSERT_EQ(luma[y * kWidth + x], luma_of(p[l.r], p[l.g], p[l.b]))
            << "stride " << l.stride << ", R at " << l.r << ", pixel " << x << "," << y;
      }
  }
}

TEST(GrayConversion, AColourFrameIsItsLumaAndChromaWhateverItsHeight) {
  // packed_rgb_to_color converts stripe by stripe, the stripes shared by OpenCV's threads: the
  // same planes as the whole-frame calls, for heights that end in a part stripe and an odd row,
  // and one of many stripes.
  constexpr int kWidth = 45;
  for (const int height : {1, 16, 17, 37, 481}) {
    std::vector<std::uint8_t> bgr(3 * kWidth * height);
    for (std::size_t i = 0; i < bgr.size(); ++i) bgr[i] = static_cast<std::uint8_t>(i * 53 + 7);
    std::vector<std::uint8_t> planes;
    const ColorView c =
        packed_rgb_to_color(&bgr[2], &bgr[1], &bgr[0], 3, 3 * kWidth, kWidth, height, planes);
    const int cw = (kWidth + 1) / 2, ch = (height + 1) / 2;
    std::vector<std::uint8_t> luma(kWidth * height), u(cw * ch), v(cw * ch);
    packed_rgb_to_luma(&bgr[2], &bgr[1], &bgr[0], 3, 3 * kWidth, kWidth, height, luma.data(),
                       kWidth);
    packed_rgb_to_chroma(&bgr[2], &bgr[1], &bgr[0], 3, 3 * kWidth, kWidth, height, u.data(),
                         v.data(), cw);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < kWidth; ++x)
        ASSERT_EQ(c.luma.data[y * c.luma.stride + x], luma[y * kWidth + x]) << height;
    for (int y = 0; y < ch; ++y)
      for (int x = 0; x < cw; ++x) {
        ASSERT_EQ(c.chroma.u[y * c.chroma.stride + x], u[y * cw + x]) << height;
        ASSERT_EQ(c.chroma.v[y * c.chroma.stride + x], v[y * cw + x]) << height;
      }
  }
}

// The same for chroma: rows long enough for the vectorised path (16 pixels of a row pair at a
// time) and a scalar tail, odd widths and heights (a last column or row of its own), every
// layout, in a buffer that ends with the last pixel: each block's chroma is that of its sums.
TEST(GrayConversion, WideRowsGiveChromaOfEveryBlockInEveryLayout) {
  struct Layout {
    int stride, r, g, b;
  };
  const Layout layouts[] = {{3, 0, 1, 2}, {3, 2, 1, 0}, {4, 0, 1, 2},
                            {4, 2, 1, 0}, {4, 1, 2, 3}, {4, 3, 2, 1}};
  for (const Layout& l : layouts)
    for (const int width : {33, 70, 71})
      for (const int height : {1, 2, 3, 4}) {
        std::vector<std::uint8_t> rgb(static_cast<std::size_t>(l.stride) * width * height);
        for (std::size_t i = 0; i < rgb.size(); ++i)
          rgb[i] = static_cast<std::uint8_t>(i * 53 + i / 5);
        const int cw = (width + 1) / 2, ch = (height + 1) / 2;
        std::vector<std::uint8_t> u(static_cast<std::size_t>(cw) * ch),
            v(static_cast<std::size_t>(cw) * ch);
        packed_rgb_to_chroma(&rgb[l.r], &rgb[l.g], &rgb[l.b], l.stride, l.stride * width, width,
                             height, u.data(), v.data(), cw);
        for (int by = 0; by < ch; ++by)
          for (int bx = 0; bx < cw; ++bx) {
            int sum[3] = {0, 0, 0};
            for (int dy = 0; dy < 2; ++dy)
              for (int dx = 0; dx < 2; ++dx) {
                const int x = std::min(2 * bx + dx, width - 1);
                const int y = std::min(2 * by + dy, height - 1);
                const std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * width + x) * l.stride];
                sum[0] += p[l.r], sum[1] += p[l.g], sum[2] += p[l.b];
              }
            ASSERT_EQ(u[by * cw + bx], u_of_sums(sum[0], sum[1], sum[2]))
                << "stride " << l.stride << ", R at " << l.r << ", " << width << "x" << height
                << ", block " << bx << "," << by;
            ASSERT_EQ(v[by * cw + bx], v_of_sums(sum[0], sum[1], sum[2]))
                << "stride " << l.stride << ", R at " << l.r << ", " << width << "x" << height
                << ", block " << bx << "," << by;
          }
      }
}

// The chroma of every 2×2 block is its mean colour's (a last odd row or column: its own pixels'),
// at video range: a neutral colour 128, pure blue's Cb and pure red's Cr 240.
TEST(GrayConversion, ChromaOfEachBlocksMeanColourAtVideoRange) {
  const int width = 3, height = 3;  // odd: the last column and row are blocks of their own
  std::vector<std::uint8_t> rgb(width * height * 3, 0);
  const auto set = [&](int x, int y, int r, int g, int b) {
    std::uint8_t* p = &rgb[(y * width + x) * 3];
    p[0] = static_cast<std::uint8_t>(r), p[1] = static_cast<std::uint8_t>(g);
    p[2] = static_cast<std::uint8_t>(b);
  };
  set(0, 0, 255, 0, 0), set(1, 0, 0, 0, 255), set(0, 1, 255, 0, 0), set(1, 1, 0, 0, 255);
  set(2, 0, 0, 0, 255), set(2, 1, 0, 0, 255);                         // the last column: blue
  set(0, 2, 255, 0, 0), set(1, 2, 255, 0, 0), set(2, 2, 90, 90, 90);  // the last row
  std::vector<std::uint8_t> u(4), v(4);
  packed_rgb_to_chroma(&rgb[0], &rgb[1], &rgb[2], 3, width * 3, width, height, u.data(), v.data(),
                       2);
  EXPECT_EQ(u[0], u_of_sums(2 * 255, 0, 2 * 255));  // half red, half blue: magenta's mean
  EXPECT_EQ(v[0], v_of_sums(2 * 255, 0, 2 * 255));
  EXPECT_EQ(u[1], 240);  // blue
  EXPECT_EQ(v[1], v_of(0, 0, 255));
  EXPECT_EQ(u[2], u_of(255, 0, 0));  // red
  EXPECT_EQ(v[2], 240);
  EXPECT_EQ(u[3], 128);  // gray
  EXPECT_EQ(v[3], 128);
  EXPECT_EQ(u_of(255, 255, 255), 128);
  EXPECT_EQ(luma_of(255, 255, 255), 235);
  EXPECT_EQ(luma_of(0, 0, 0), kVideoBlack);
}

// A full-range frame (GRAY8, JPEG's YUV) at video range: luma 0–255 to 16–235, chroma 0–255 to
// 16–240 about 128, in every chroma layout, the exposure carried over.
TEST(GrayConversion, FullRangeMappedToVideoRange) {
  const int width = 4, height = 2;
  const std::uint8_t luma[] = {0, 128, 255, 10, 20, 30, 40, 50};
  // NV12-like: U, V pairs (pixel stride 2), one per 2×2 block, rows padded to 6 bytes.
  const std::uint8_t uv[] = {0, 255, 128, 64, 0xAB, 0xAB};
  ColorView full;
  full.luma = ImageView(luma, width, height, width);
  full.chroma = ChromaView{uv, uv + 1, 6, 2, 1, 1};
  full.exposure.gain = 2;
  std::vector<std::uint8_t> planes;
  const ColorView video = full_to_video_range(full, planes);
  EXPECT_EQ(video.luma.at(0, 0), 16);
  EXPECT_EQ(video.luma.at(1, 0), 126);  // 16 + 128 · 219 / 255 = 125.9
  EXPECT_EQ(video.luma.at(2, 0), 235);
  EXPECT_EQ(video.chroma.u_at(0, 0), 16);
  EXPECT_EQ(video.chroma.v_at(0, 0), 240);
  EXPECT_EQ(video.chroma.u_at(2, 1), 128);
  EXPECT_EQ(video.chroma.v_at(3, 1), 72);  // 128 - 64 · 224 / 255 = 71.8
  EXPECT_EQ(video.exposure.gain, 2);
  // Gray: the luma alone.
  full.chroma = {};
  const ColorView gray = full_to_video_range(full, planes);
  EXPECT_FALSE(gray.has_chroma());
  EXPECT_EQ(gray.luma.at(3, 1), std::lround(16 + 50 * 219.0 / 255.0));
}

// YUY2's luma (every second byte from the first), UYVY's (from the second), chroma planes
// (stride 1) and any other pixel stride: every width, rows top-down or bottom-up, padding kept.
TEST(GrayConversion, GatherOneComponentOfAPackedFormat) {
  for (int pixel_stride : {1, 2, 3, 4}) {
    for (int width : {1, 15, 16, 17, 37, 64}) {
      for (int first : {0, 1}) {
        for (bool bottom_up : {false, true}) {
          SCOPED_TRACE(::testing::Message() << "stride " << pixel_stride << " width " << width
                                            << " first " << first << " bottom-up " << bottom_up);
          const int height = 3, row_stride = width * pixel_stride + 5, out_stride = width + 3;
          std::vector<std::uint8_t> in(static_cast<std::size_t>(row_stride) * height);
          for (std::size_t i = 0; i < in.size(); ++i) in[i] = static_cast<std::uint8_t>(i * 7 + 3);
          std::vector<std::uint8_t> out(static_cast<std::size_t>(out_stride) * height, 0xCD);
          const std::uint8_t* start =
              in.data() + first + (bottom_up ? (height - 1) * row_stride : 0);
          gather_component(start, pixel_stride, bottom_up ? -row_stride : row_stride, width, height,
                           out.data(), out_stride);
          for (int y = 0; y < height; ++y) {
            const int row = bottom_up ? height - 1 - y : y;
            for (int x = 0; x < width; ++x)
              ASSERT_EQ(out[y * out_stride + x], in[row * row_stride + first + x * pixel_stride])
                  << x << "," << y;
            for (int x = width; x < out_stride; ++x) ASSERT_EQ(out[y * out_stride + x], 0xCD);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace projtrack
