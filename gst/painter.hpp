// Writes colours into a mapped video frame of any format the element accepts, one component at a
// time through the format's planes, offsets and subsampling: what the overlay and its text panel
// draw with.
#pragma once

#include <gst/video/video.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "font.hpp"
#include "projtrack/color_conversion.hpp"
#include "projtrack/geometry.hpp"

namespace projtrack::gst {

struct Rgb {
  std::uint8_t r, g, b;
};

// Writes colours into any 8-bit planar, semi-planar or packed format, one component at a time.
class Painter {
 public:
  explicit Painter(GstVideoFrame* frame)
      : frame_(frame),
        info_(frame->info.finfo),
        width_(GST_VIDEO_FRAME_WIDTH(frame)),
        height_(GST_VIDEO_FRAME_HEIGHT(frame)),
        components_(GST_VIDEO_FRAME_N_COMPONENTS(frame)) {}

  int width() const { return width_; }
  int height() const { return height_; }

  void set(int x, int y, Rgb c) { write(x, y, c, false); }
  void tint(int x, int y, Rgb c) { write(x, y, c, true); }
  // Three quarters of the way to black, so that text on it reads whatever the picture.
  void darken(int x, int y) {
    if (!inside(x, y)) return;
    const bool yuv = GST_VIDEO_FORMAT_INFO_IS_YUV(info_);
    for (int k = 0; k < components_ && k < 3; ++k) {
      std::uint8_t* p = pixel(x, y, k);
      const int black = yuv ? (k == 0 ? 16 : 128) : 0;
      *p = static_cast<std::uint8_t>(black + (*p - black) / 4);
    }
  }

  void line(Point2d a, Point2d b, Rgb c) {
    const double steps = std::ceil(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)));
    const int n = static_cast<int>(std::min(steps, 100000.0));
    for (int i = 0; i <= n; ++i) {
      const double t = n ? static_cast<double>(i) / n : 0.0;
      set(static_cast<int>(std::lround(a.x + t * (b.x - a.x))),
          static_cast<int>(std::lround(a.y + t * (b.y - a.y))), c);
    }
  }
  void outline(const Rect& r, Rgb c) {
    const Point2d tl{double(r.x), double(r.y)}, br{double(r.right() - 1), double(r.bottom() - 1)};
    line(tl, {br.x, tl.y}, c);
    line({br.x, tl.y}, br, c);
    line(br, {tl.x, br.y}, c);
    line({tl.x, br.y}, tl, c);
  }
  // Every pixel of `r` within the frame, through `paint(x, y)`.
  template <class Paint>
  void fill(const Rect& r, Paint&& paint) {
    const Rect in = clip_to_frame(r, width_, height_);
    for (int y = in.y; y < in.bottom(); ++y)
      for (int x = in.x; x < in.right(); ++x) paint(x, y);
  }
  void square(Point2i p, int radius, Rgb c) {
    // The inner point may be anywhere, INT_MAX included: moved first to just outside the frame
    // (where the square still misses it), so that the square's corners do not overflow.
    const Point2i q{std::clamp(p.x, -radius - 1, width_ + radius),
                    std::clamp(p.y, -radius - 1, height_ + radius)};
    fill({q.x - radius, q.y - radius, 2 * radius + 1, 2 * radius + 1},
         [&](int x, int y) { set(x, y, c); });
  }
  void cross(Point2d p, int radius, Rgb c) {
    line({p.x - radius, p.y}, {p.x + radius, p.y}, c);
    line({p.x, p.y - radius}, {p.x, p.y + radius}, c);
  }
  // `text` from its top-left corner, each font pixel a scale × scale square.
  // `text` in printable ASCII (see drawable()).
  void text(int left, int top, int scale, const std::string& text, Rgb c) {
    for (std::size_t i = 0; i < text.size(); ++i) {
      const Glyph& g = glyph(text[i]);
      const int x0 = left + static_cast<int>(i) * (kGlyphWidth + 1) * scale;
      for (int row = 0; row < kGlyphHeight; ++row)
        for (int col = 0; col < kGlyphWidth; ++col)
          if (g[row] >> (kGlyphWidth - 1 - col) & 1)
            fill({x0 + col * scale, top + row * scale, scale, scale},
                 [&](int x, int y) { set(x, y, c); });
    }
  }

 private:
  bool inside(int x, int y) const { return Rect{0, 0, width_, height_}.contains({x, y}); }
  std::uint8_t* pixel(int x, int y, int k) const {
    return static_cast<std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame_, k)) +
           (y >> GST_VIDEO_FORMAT_INFO_H_SUB(info_, k)) * GST_VIDEO_FRAME_COMP_STRIDE(frame_, k) +
           (x >> GST_VIDEO_FORMAT_INFO_W_SUB(info_, k)) * GST_VIDEO_FRAME_COMP_PSTRIDE(frame_, k);
  }

  // Component values of an RGB colour in this frame's colour space (BT.601, as the gray).
  void components(Rgb c, std::uint8_t out[4]) const {
    if (GST_VIDEO_FORMAT_INFO_IS_YUV(info_)) {
      out[0] = luma_of(c.r, c.g, c.b);  // video range, as the library reads RGB
      out[1] = u_of(c.r, c.g, c.b);
      out[2] = v_of(c.r, c.g, c.b);
    } else if (GST_VIDEO_FORMAT_INFO_IS_GRAY(info_)) {
      out[0] = gray_of(c.r, c.g, c.b);
    } else {
      out[0] = c.r;
      out[1] = c.g;
      out[2] = c.b;
    }
    out[3] = 255;  // opaque alpha
  }

  void write(int x, int y, Rgb c, bool blend) {
    if (!inside(x, y)) return;
    if (c.r != colour_.r || c.g != colour_.g || c.b != colour_.b || !converted_) {
      components(c, values_);  // once per colour change, not per pixel
      colour_ = c;
      converted_ = true;
    }
    const std::uint8_t* v = values_;
    for (int k = 0; k < components_; ++k) {
      std::uint8_t* p = pixel(x, y, k);
      *p = blend && k != 3 ? static_cast<std::uint8_t>((*p + v[k] + 1) / 2) : v[k];
    }
  }

  GstVideoFrame* frame_;
  const GstVideoFormatInfo* info_;
  int width_, height_, components_;
  Rgb colour_{0, 0, 0};
  std::uint8_t values_[4] = {};
  bool converted_ = false;
};

}  // namespace projtrack::gst
