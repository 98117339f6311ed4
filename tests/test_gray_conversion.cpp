// Packed RGB to gray.
#include <gtest/gtest.h>

#include <vector>

#include "gray_conversion.hpp"

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

}  // namespace
}  // namespace projtrack
