#include "overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gray_conversion.hpp"

namespace projtrack::gst {

namespace {

struct Rgb {
  std::uint8_t r, g, b;
};

constexpr Rgb kOutline{0, 255, 0}, kFill{0, 255, 255}, kGrid{255, 0, 255}, kBlock{64, 128, 255},
    kRay{0, 255, 0}, kHit{255, 255, 0}, kBox{255, 0, 0}, kCentroid{255, 0, 0},
    kInnerPoint{255, 255, 0};

// Writes colours into any 8-bit planar, semi-planar or packed format, one component at a time.
class Painter {
 public:
  explicit Painter(GstVideoFrame* frame)
      : frame_(frame),
        info_(frame->info.finfo),
        width_(GST_VIDEO_FRAME_WIDTH(frame)),
        height_(GST_VIDEO_FRAME_HEIGHT(frame)),
        components_(GST_VIDEO_FRAME_N_COMPONENTS(frame)) {}

  void set(int x, int y, Rgb c) { write(x, y, c, false); }
  void tint(int x, int y, Rgb c) { write(x, y, c, true); }

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
  void square(Point2i p, int radius, Rgb c) {
    // The inner point may be anywhere, INT_MAX included: moved first to just outside the frame
    // (where the square still misses it), so that the square's corners do not overflow.
    const Point2i q{std::clamp(p.x, -radius - 1, width_ + radius),
                    std::clamp(p.y, -radius - 1, height_ + radius)};
    const Rect r = clip_to_frame({q.x - radius, q.y - radius, 2 * radius + 1, 2 * radius + 1},
                                 width_, height_);
    for (int y = r.y; y < r.bottom(); ++y)
      for (int x = r.x; x < r.right(); ++x) set(x, y, c);
  }
  void cross(Point2d p, int radius, Rgb c) {
    line({p.x - radius, p.y}, {p.x + radius, p.y}, c);
    line({p.x, p.y - radius}, {p.x, p.y + radius}, c);
  }

 private:
  // Component values of an RGB colour in this frame's colour space (BT.601, as the gray).
  void components(Rgb c, std::uint8_t out[4]) const {
    if (GST_VIDEO_FORMAT_INFO_IS_YUV(info_)) {
      out[0] = static_cast<std::uint8_t>(16 + (66 * c.r + 129 * c.g + 25 * c.b + 128) / 256);
      out[1] = static_cast<std::uint8_t>(128 + (-38 * c.r - 74 * c.g + 112 * c.b + 128) / 256);
      out[2] = static_cast<std::uint8_t>(128 + (112 * c.r - 94 * c.g - 18 * c.b + 128) / 256);
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
    if (!Rect{0, 0, width_, height_}.contains({x, y})) return;
    if (c.r != colour_.r || c.g != colour_.g || c.b != colour_.b || !converted_) {
      components(c, values_);  // once per colour change, not per pixel
      colour_ = c;
      converted_ = true;
    }
    const std::uint8_t* v = values_;
    for (int k = 0; k < components_; ++k) {
      auto* p =
          static_cast<std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame_, k)) +
          (y >> GST_VIDEO_FORMAT_INFO_H_SUB(info_, k)) * GST_VIDEO_FRAME_COMP_STRIDE(frame_, k) +
          (x >> GST_VIDEO_FORMAT_INFO_W_SUB(info_, k)) * GST_VIDEO_FRAME_COMP_PSTRIDE(frame_, k);
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

}  // namespace

void draw_overlay(GstVideoFrame* frame, Method method, const Features& features,
                  const Trace& trace) {
  Painter paint(frame);
  const bool grid = method_info(method).trace == TraceKind::GridLines;
  for (const Trace::Run& run : trace.runs) {
    for (int y = run.first.y; y <= run.last.y; ++y)
      for (int x = run.first.x; x <= run.last.x; ++x) {
        if (grid)
          paint.set(x, y, kGrid);
        else
          paint.tint(x, y, kFill);
      }
  }
  for (const Trace::Block& b : trace.blocks) {
    for (int y = b.rect.y; y < b.rect.bottom(); ++y)
      for (int x = b.rect.x; x < b.rect.right(); ++x) paint.tint(x, y, kBlock);
    paint.outline(b.rect, kBlock);
  }
  // The rays of the last iteration (the inner-point updates' rays, iteration 0, are left out).
  const int last = trace.last_recorded_iteration();
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == last && last > 0) paint.line(r.origin, r.hit, kRay);
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == last && last > 0) paint.square(round_to_pixel(r.hit), 1, kHit);
  // The silhouette the estimator ran on (appearance model), two pixels wide to stay visible.
  for (const Point2i& p : trace.outline) {
    paint.set(p.x, p.y, kOutline);
    paint.set(p.x + 1, p.y, kOutline);
  }
  if (features.valid()) {
    paint.outline(features.bbox, kBox);
    paint.cross(features.centroid, 6, kCentroid);
  }
  if (features.status != Status::NoInnerPoint) paint.square(features.inner_point, 2, kInnerPoint);
}

}  // namespace projtrack::gst
