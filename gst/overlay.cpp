#include "overlay.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "edges/gray_conversion.hpp"
#include "font.hpp"

namespace projtrack::gst {

namespace {

struct Rgb {
  std::uint8_t r, g, b;
};

constexpr Rgb kOutline{0, 255, 0}, kFill{0, 255, 255}, kGrid{255, 0, 255}, kBlock{64, 128, 255},
    kRay{0, 255, 0}, kHit{255, 255, 0}, kBox{255, 0, 0}, kHeldBox{255, 160, 0},
    kCentroid{255, 0, 0}, kInnerPoint{255, 255, 0}, kText{255, 255, 255};
// The status line's colour: green while tracking, red when lost, yellow while searching, white
// when waiting for an inner point, orange when the settings or the frame are wrong.
constexpr Rgb kTracking{64, 255, 64}, kLost{255, 80, 80}, kSearching{255, 230, 0},
    kWaiting{255, 255, 255}, kProblem{255, 160, 0};

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

Rgb status_colour(TrackStatus s) {
  switch (s) {
    case TrackStatus::Ok:
    case TrackStatus::ReachedBorder:
    case TrackStatus::CoversFrame:
      return kTracking;
    case TrackStatus::Lost:
    case TrackStatus::OverBudget:
      return kLost;
    case TrackStatus::Searching:
      return kSearching;
    case TrackStatus::NoInnerPoint:
      return kWaiting;
    default:
      return kProblem;
  }
}

std::string headline(const TrackResult& r) {
  switch (r.status) {
    case TrackStatus::Ok:
      return "TRACKING";
    case TrackStatus::ReachedBorder:
      return "TRACKING (at the frame border)";
    case TrackStatus::CoversFrame:
      return "TRACKING (covers the frame)";
    case TrackStatus::Lost:
      return "LOST";
    case TrackStatus::Searching:
      return "SEARCHING";
    case TrackStatus::NoInnerPoint:
      return "WAITING";
    case TrackStatus::InvalidParameters:
      return "INVALID SETTINGS";
    default: {
      std::string name(status_name(r.status));
      for (char& c : name) c = c == '-' ? ' ' : static_cast<char>(std::toupper(c));
      return name;
    }
  }
}

std::string format(const char* fmt, double a, double b, double c) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, fmt, a, b, c);
  return buffer;
}

// `line` cut at spaces into lines of at most `columns` characters (a longer word is cut).
void wrap(const std::string& line, std::size_t columns, std::vector<std::string>& out) {
  std::size_t start = 0;
  while (line.size() - start > columns) {
    std::size_t cut = line.rfind(' ', start + columns);
    if (cut == std::string::npos || cut <= start) cut = start + columns;
    out.push_back(line.substr(start, cut - start));
    start = line[cut] == ' ' ? cut + 1 : cut;
  }
  out.push_back(line.substr(start));
}

}  // namespace

std::vector<std::string> overlay_text(const TrackResult& r, Method method) {
  const std::string& detail = r.detail.empty() ? r.features.detail : r.detail;
  std::vector<std::string> lines{headline(r) + (detail.empty() ? "" : ": " + detail)};
  if (r.has_pose)
    lines.push_back(format("x %+.2f  y %+.2f  depth %.2f", r.pose.x, r.pose.y, r.pose.depth));
  if (r.features.valid()) {
    const char* what = has_features(r.status) ? "centroid" : "last seen at";
    lines.push_back(std::string(what) + format(" %.0f, %.0f  area %.0f px", r.features.centroid.x,
                                               r.features.centroid.y, r.features.area));
  }
  if (r.gesture != Gesture::None) {  // PUSH, PRESS, RELEASE
    std::string g(gesture_name(r.gesture));
    for (char& c : g) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    lines.push_back(g);
  }
  lines.push_back(std::string("method ") + method_info(method).nick);
  return lines;
}

int text_scale(int frame_height) { return std::clamp(frame_height / 240, 1, 8); }

void draw_overlay(GstVideoFrame* frame, Method method, const TrackResult& result,
                  const Trace& trace) {
  Painter paint(frame);
  const Features& features = result.features;
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
    paint.fill(b.rect, [&](int x, int y) { paint.tint(x, y, kBlock); });
    paint.outline(b.rect, kBlock);
  }
  // The rays of the last iteration (the inner-point updates' rays, iteration 0, are left out).
  const int last = trace.last_recorded_iteration();
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == last && last > 0) paint.line(r.origin, r.hit, kRay);
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == last && last > 0) paint.square(round_to_pixel(r.hit), 1, kHit);
  // The silhouette the estimator ran on (appearance model), as thick as the text's strokes.
  const int scale = text_scale(paint.height());
  for (const Point2i& p : trace.outline)
    paint.fill({p.x, p.y, scale, scale}, [&](int x, int y) { paint.set(x, y, kOutline); });
  const bool tracking = has_features(result.status);
  if (features.valid()) {
    paint.outline(features.bbox, tracking ? kBox : kHeldBox);
    if (tracking) paint.cross(features.centroid, 3 * scale + 3, kCentroid);
  }
  if (tracking) paint.square(features.inner_point, scale, kInnerPoint);

  // The text panel, wrapped to the frame's width.
  const int advance = (kGlyphWidth + 1) * scale, line_height = (kGlyphHeight + 1) * scale;
  const int pad = 2 * scale;
  const auto columns = static_cast<std::size_t>(std::max(1, (paint.width() - 2 * pad) / advance));
  std::vector<std::string> lines;
  const std::vector<std::string> text = overlay_text(result, method);
  std::size_t status_lines = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    wrap(drawable(text[i]), columns, lines);  // the font's characters, so widths count right
    if (i == 0) status_lines = lines.size();
  }
  std::size_t longest = 0;
  for (const std::string& l : lines) longest = std::max(longest, l.size());
  const Rect panel{0, 0, 2 * pad + static_cast<int>(longest) * advance - scale,
                   2 * pad + static_cast<int>(lines.size()) * line_height - scale};
  paint.fill(panel, [&](int x, int y) { paint.darken(x, y); });
  const Rgb headline_colour = status_colour(result.status);
  for (std::size_t i = 0; i < lines.size(); ++i)
    paint.text(pad, pad + static_cast<int>(i) * line_height, scale, lines[i],
               i < status_lines ? headline_colour : kText);
}

}  // namespace projtrack::gst
