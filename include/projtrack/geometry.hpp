// Small plain geometry types of the public API (kept free of OpenCV so users need not include it).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace projtrack {

struct Point2i {
  int x = 0;
  int y = 0;
  friend bool operator==(Point2i a, Point2i b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(Point2i a, Point2i b) { return !(a == b); }
};

struct Point2d {
  double x = 0.0;
  double y = 0.0;
};

inline double distance(Point2d a, Point2d b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline double distance(Point2i a, Point2i b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline Point2d to_double(Point2i p) { return {static_cast<double>(p.x), static_cast<double>(p.y)}; }
inline Point2i round_to_pixel(Point2d p) {
  return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))};
}

// Pixel rectangle: columns [x, x + width), rows [y, y + height). The operations are those of
// OpenCV's cv::Rect_: contains, & (intersection) and | (union); clipping to a frame is
// `r & Rect{0, 0, width, height}` (clip_to_frame). They work in 64 bits, so no rectangle overflows
// them; a result beyond the int range is clamped to it.
struct Rect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;

  bool empty() const { return width <= 0 || height <= 0; }
  int right() const { return x + width; }    // one past the last column
  int bottom() const { return y + height; }  // one past the last row
  bool contains(Point2i p) const {           // (p.x - x < width in 64 bits: right() may overflow)
    return x <= p.x && p.x - static_cast<long long>(x) < width && y <= p.y &&
           p.y - static_cast<long long>(y) < height;
  }
  friend bool operator==(const Rect& a, const Rect& b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
  }
  friend bool operator!=(const Rect& a, const Rect& b) { return !(a == b); }
  // The pixels in both; Rect{} when there are none.
  friend Rect operator&(const Rect& a, const Rect& b);
  // The smallest rectangle holding both; an empty one adds nothing.
  friend Rect operator|(const Rect& a, const Rect& b);
  Rect& operator&=(const Rect& r) { return *this = *this & r; }
  Rect& operator|=(const Rect& r) { return *this = *this | r; }
};

namespace detail {
// A rectangle's corners in 64 bits: [x0, x1) × [y0, y1).
struct Corners {
  long long x0, y0, x1, y1;
};
inline Corners corners(const Rect& r) {
  return {r.x, r.y, static_cast<long long>(r.x) + r.width, static_cast<long long>(r.y) + r.height};
}
inline Rect from_corners(const Corners& c) {
  const auto to_int = [](long long v) {
    return static_cast<int>(
        std::clamp<long long>(v, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
  };
  return {to_int(c.x0), to_int(c.y0), to_int(c.x1 - c.x0), to_int(c.y1 - c.y0)};
}
}  // namespace detail

inline Rect operator&(const Rect& a, const Rect& b) {
  const detail::Corners p = detail::corners(a), q = detail::corners(b);
  const detail::Corners c{std::max(p.x0, q.x0), std::max(p.y0, q.y0), std::min(p.x1, q.x1),
                          std::min(p.y1, q.y1)};
  if (c.x1 <= c.x0 || c.y1 <= c.y0) return {};
  return detail::from_corners(c);
}

inline Rect operator|(const Rect& a, const Rect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const detail::Corners p = detail::corners(a), q = detail::corners(b);
  return detail::from_corners(
      {std::min(p.x0, q.x0), std::min(p.y0, q.y0), std::max(p.x1, q.x1), std::max(p.y1, q.y1)});
}

// `r` clipped to a width × height frame: the part of it in the frame, Rect{} when none.
inline Rect clip_to_frame(const Rect& r, int width, int height) {
  return r & Rect{0, 0, width, height};
}

// Grows a bounding box pixel by pixel without branches on the empty case in hot loops.
class BoundsAccumulator {
 public:
  void add(int x, int y) {
    if (x < x0_) x0_ = x;
    if (x > x1_) x1_ = x;
    if (y < y0_) y0_ = y;
    if (y > y1_) y1_ = y;
  }
  void add_run(int x_first, int x_last, int y) {
    add(x_first, y);
    add(x_last, y);
  }
  void add(const Rect& r) {
    if (r.empty()) return;
    add(r.x, r.y);
    add(r.right() - 1, r.bottom() - 1);
  }
  Rect rect() const {
    if (x1_ < x0_) return {};
    return {x0_, y0_, x1_ - x0_ + 1, y1_ - y0_ + 1};
  }

 private:
  int x0_ = 1 << 30, y0_ = 1 << 30, x1_ = -(1 << 30), y1_ = -(1 << 30);
};

}  // namespace projtrack
