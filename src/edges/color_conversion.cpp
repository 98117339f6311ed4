#include "projtrack/color_conversion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/core/utility.hpp>

namespace projtrack {

namespace {

// The pixels [0, returned) of one row, 16 at a time: OpenCV's universal intrinsics split packed
// pixels into channel vectors (the compiler's own vectorisation of the stride-3 gather below runs
// at a fifth of the speed), and each sum is the same integers as luma_of()'s. `first` is the
// row's byte of the component with the lowest offset; `at` says which channel vector holds R, G
// and B; `spill`: a 4-byte pixel read from `first` may take the next pixel's first byte (xRGB's
// R is its second), so the row's last pixel is left to the scalar loop.
template <int kPixelStride>
int luma_row_vectorised(const std::uint8_t* first, const std::array<int, 3>& at, bool spill,
                        int width, std::uint8_t* out) {
  int x = 0;
#if CV_SIMD128
  const cv::v_uint16x8 wr = cv::v_setall_u16(66), wg = cv::v_setall_u16(129),
                       wb = cv::v_setall_u16(25), half = cv::v_setall_u16(128),
                       black = cv::v_setall_u16(16);
  for (; x + 16 + (spill ? 1 : 0) <= width; x += 16) {
    // A frame fresh from a camera or decoder is in memory, not the cache: read 2 KB ahead, this
    // loop ran at a third of its cached speed on it (854×480: 0.57 against 0.19 ms). A prefetch
    // past the frame's end is a hint, never a read.
    __builtin_prefetch(first + kPixelStride * x + 2048);
    cv::v_uint8x16 c[4];
    if constexpr (kPixelStride == 4)
      cv::v_load_deinterleave(first + 4 * x, c[0], c[1], c[2], c[3]);
    else
      cv::v_load_deinterleave(first + 3 * x, c[0], c[1], c[2]);
    cv::v_uint16x8 r[2], g[2], b[2], y[2];
    cv::v_expand(c[at[0]], r[0], r[1]);
    cv::v_expand(c[at[1]], g[0], g[1]);
    cv::v_expand(c[at[2]], b[0], b[1]);
    // Wrapping (not saturating) 16-bit arithmetic: the largest sum, 220 × 255 + 128, fits.
    for (int k = 0; k < 2; ++k) {
      const cv::v_uint16x8 sum =
          cv::v_add_wrap(cv::v_add_wrap(cv::v_mul_wrap(r[k], wr), cv::v_mul_wrap(g[k], wg)),
                         cv::v_add_wrap(cv::v_mul_wrap(b[k], wb), half));
      y[k] = cv::v_add_wrap(sum >> 8, black);
    }
    cv::v_store(out + x, cv::v_pack(y[0], y[1]));
  }
#endif
  return x;
}

template <int kPixelStride>
void convert(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
             std::ptrdiff_t row_stride, int width, int height, std::uint8_t* luma,
             std::ptrdiff_t luma_stride) {
  const std::uint8_t* first = std::min({r, g, b});
  const std::array<int, 3> at{static_cast<int>(r - first), static_cast<int>(g - first),
                              static_cast<int>(b - first)};
  // Components within one pixel (every packed RGB format): else the scalar loop alone.
  const bool packed = std::max({at[0], at[1], at[2]}) < kPixelStride;
  for (int y = 0; y < height; ++y) {
    const std::ptrdiff_t row = y * row_stride;
    std::uint8_t* out = luma + y * luma_stride;
    int x = packed
                ? luma_row_vectorised<kPixelStride>(first + row, at, kPixelStride == 4, width, out)
                : 0;
    for (; x < width; ++x) {
      const std::ptrdiff_t i = row + static_cast<std::ptrdiff_t>(x) * kPixelStride;
      out[x] = luma_of(r[i], g[i], b[i]);
    }
  }
}

}  // namespace

void packed_rgb_to_luma(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                        int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                        std::uint8_t* luma, std::ptrdiff_t luma_stride) {
  if (pixel_stride == 4)
    convert<4>(r, g, b, row_stride, width, height, luma, luma_stride);
  else
    convert<3>(r, g, b, row_stride, width, height, luma, luma_stride);
}

void packed_rgb_to_chroma(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                          int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                          std::uint8_t* u, std::uint8_t* v, std::ptrdiff_t chroma_stride) {
  for (int y = 0; y < height; y += 2) {
    const std::ptrdiff_t row = y * row_stride;
    const std::ptrdiff_t below = y + 1 < height ? row_stride : 0;  // the last odd row: itself
    std::uint8_t* uo = u + (y / 2) * chroma_stride;
    std::uint8_t* vo = v + (y / 2) * chroma_stride;
    for (int x = 0; x < width; x += 2) {
      const std::ptrdiff_t i = row + static_cast<std::ptrdiff_t>(x) * pixel_stride;
      const std::ptrdiff_t right = x + 1 < width ? pixel_stride : 0;  // the last odd column
      // The block's mean colour, as an encoder's or videoconvert's I420 holds it: its top-left
      // pixel alone would give an RGB frame's blocks other colours than the same picture's I420.
      const int rs = r[i] + r[i + right] + r[i + below] + r[i + below + right];
      const int gs = g[i] + g[i + right] + g[i + below] + g[i + below + right];
      const int bs = b[i] + b[i + right] + b[i + below] + b[i + below + right];
      uo[x / 2] = u_of_sums(rs, gs, bs);
      vo[x / 2] = v_of_sums(rs, gs, bs);
    }
  }
}

namespace {
// The pixel stride as a constant, and rows that do not overlap, let the compiler vectorise the
// loop: YUY2's luma (stride 2) is gathered at 4× the speed of the loop with a variable stride
// (docs/element.md, "Formats").
template <int kPixelStride>
void gather(const std::uint8_t* first, std::ptrdiff_t row_stride, int width, int height,
            std::uint8_t* out, std::ptrdiff_t out_stride) {
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* __restrict in = first + y * row_stride;
    std::uint8_t* __restrict o = out + y * out_stride;
    for (int x = 0; x < width; ++x) o[x] = in[static_cast<std::ptrdiff_t>(x) * kPixelStride];
  }
}
}  // namespace

void gather_component(const std::uint8_t* first, int pixel_stride, std::ptrdiff_t row_stride,
                      int width, int height, std::uint8_t* out, std::ptrdiff_t out_stride) {
  if (pixel_stride == 2) return gather<2>(first, row_stride, width, height, out, out_stride);
  if (pixel_stride == 1) return gather<1>(first, row_stride, width, height, out, out_stride);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* in = first + y * row_stride;
    std::uint8_t* o = out + y * out_stride;
    for (int x = 0; x < width; ++x) o[x] = in[static_cast<std::ptrdiff_t>(x) * pixel_stride];
  }
}

ColorView packed_rgb_to_color(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
                              int pixel_stride, std::ptrdiff_t row_stride, int width, int height,
                              std::vector<std::uint8_t>& planes) {
  const std::size_t luma = static_cast<std::size_t>(width) * height;
  const int cw = (width + 1) / 2, ch = (height + 1) / 2;
  const std::size_t chroma = static_cast<std::size_t>(cw) * ch;
  planes.resize(luma + 2 * chroma);
  // Luma and chroma stripe by stripe: the frame's rows are read from memory once, the chroma
  // finding them still in the cache (a frame fresh from a camera or decoder is not). The stripes
  // are independent: OpenCV's threads share them (reading a frame from memory is the cost).
  constexpr int kStripe = 16;  // rows: even, so that each stripe holds whole chroma rows
  const int stripes = (height + kStripe - 1) / kStripe;
  cv::parallel_for_(cv::Range(0, stripes), [&](const cv::Range& range) {
    for (int y = range.start * kStripe; y < std::min(height, range.end * kStripe); y += kStripe) {
      const int rows = std::min(kStripe, height - y);
      const std::ptrdiff_t in = y * row_stride;
      const std::ptrdiff_t c = static_cast<std::ptrdiff_t>(y / 2) * cw;
      packed_rgb_to_luma(r + in, g + in, b + in, pixel_stride, row_stride, width, rows,
                         planes.data() + static_cast<std::ptrdiff_t>(y) * width, width);
      packed_rgb_to_chroma(r + in, g + in, b + in, pixel_stride, row_stride, width, rows,
                           planes.data() + luma + c, planes.data() + luma + chroma + c, cw);
    }
  });
  ColorView c;
  c.luma = ImageView(planes.data(), width, height, width);
  c.chroma = {planes.data() + luma, planes.data() + luma + chroma, cw, 1, 1, 1};
  return c;
}

namespace {

// Full range to video range, value by value (BT.601: luma 0–255 to 16–235, chroma 0–255 to
// 16–240 about 128), rounded.
struct VideoRangeTables {
  std::array<std::uint8_t, 256> luma{}, chroma{};
  VideoRangeTables() {
    for (int v = 0; v < 256; ++v) {
      luma[v] = static_cast<std::uint8_t>(std::lround(16 + v * 219.0 / 255.0));
      chroma[v] = static_cast<std::uint8_t>(std::lround(128 + (v - 128) * 224.0 / 255.0));
    }
  }
};

const VideoRangeTables& video_range_tables() {
  static const VideoRangeTables tables;
  return tables;
}

// `width` × `height` samples `pixel_stride` bytes apart, rows `stride` apart (negative:
// bottom-up), through `table` into a plane of rows `width` apart.
void map_plane(const std::uint8_t* in, int pixel_stride, std::ptrdiff_t stride, int width,
               int height, const std::array<std::uint8_t, 256>& table, std::uint8_t* out) {
  if (pixel_stride == 1 && stride >= width) {  // a plane: OpenCV's vectorised table look-up
    const cv::Mat from(height, width, CV_8U, const_cast<std::uint8_t*>(in),
                       static_cast<std::size_t>(stride));
    cv::Mat to(height, width, CV_8U, out);
    cv::LUT(from, cv::Mat(1, 256, CV_8U, const_cast<std::uint8_t*>(table.data())), to);
    return;
  }
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = in + y * stride;
    std::uint8_t* o = out + static_cast<std::ptrdiff_t>(y) * width;
    for (int x = 0; x < width; ++x)
      o[x] = table[row[static_cast<std::ptrdiff_t>(x) * pixel_stride]];
  }
}

}  // namespace

ColorView full_to_video_range(const ColorView& full, std::vector<std::uint8_t>& planes) {
  const ImageView& l = full.luma;
  const ChromaView& c = full.chroma;
  const std::size_t luma = static_cast<std::size_t>(l.width) * l.height;
  const int cw = (l.width + (1 << c.shift_x) - 1) >> c.shift_x;
  const int ch = (l.height + (1 << c.shift_y) - 1) >> c.shift_y;
  const std::size_t chroma = full.has_chroma() ? static_cast<std::size_t>(cw) * ch : 0;
  planes.resize(luma + 2 * chroma);
  const VideoRangeTables& t = video_range_tables();
  ColorView out;
  out.exposure = full.exposure;
  map_plane(l.data, 1, l.stride, l.width, l.height, t.luma, planes.data());
  out.luma = ImageView(planes.data(), l.width, l.height, l.width);
  if (chroma == 0) return out;
  std::uint8_t* u = planes.data() + luma;
  std::uint8_t* v = u + chroma;
  map_plane(c.u, c.pixel_stride, c.stride, cw, ch, t.chroma, u);
  map_plane(c.v, c.pixel_stride, c.stride, cw, ch, t.chroma, v);
  out.chroma = {u, v, cw, 1, c.shift_x, c.shift_y};
  return out;
}

}  // namespace projtrack
