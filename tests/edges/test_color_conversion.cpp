// Packed RGB to gray; one component of a packed format gathered into a plane.
#include <gtest/gtest.h>

#include <vector>

#include "projtrack/color_conversion.hpp"

namespace projtrack {
namespace {

TEST(GrayConversion, Bt601WeightsInEveryComponentOrderAndPixelSize) {
  // Two rows of red, green, blue, white, black, padded to 23 bytes per row.
  const std::uint8_t colours[5][3] = {
      {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {0, 0, 0}};
  const std::uint8_t expected[5] = {77, 149, 29, 255, 0};
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
      packed_rgb_to_gray(&rgb[r_off], &rgb[g_off], &rgb[b_off], pixel_stride, row_stride, 5, 2,
                         gray.data(), 7);
      for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 5; ++x) EXPECT_EQ(gray[y * 7 + x], expected[x]) << pixel_stride;
        EXPECT_EQ(gray[y * 7 + 5], 0xCD);  // padding untouched
      }
    }
  }
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
