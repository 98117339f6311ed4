#include "projtrack/color_conversion.hpp"

#include <array>
#include <cmath>
#include <opencv2/core.hpp>

namespace projtrack {

namespace {
// The pixel stride as a constant lets the compiler unroll and vectorise each variant.
template <int kPixelStride>
void convert(const std::uint8_t* r, const std::uint8_t* g, const std::uint8_t* b,
             std::ptrdiff_t row_stride, int width, int height, std::uint8_t* luma,
             std::ptrdiff_t luma_stride) {
  for (int y = 0; y < height; ++y) {
    const std::ptrdiff_t row = y * row_stride;
    std::uint8_t* out = luma + y * luma_stride;
    for (int x = 0; x < width; ++x) {
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
  packed_rgb_to_luma(r, g, b, pixel_stride, row_stride, width, height, planes.data(), width);
  packed_rgb_to_chroma(r, g, b, pixel_stride, row_stride, width, height, planes.data() + luma,
                       planes.data() + luma + chroma, cw);
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
