// Small plain geometry types of the public API (kept free of OpenCV so users need not include it).
#pragma once

#include <cmath>

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

// Pixel rectangle: columns [x, x + width), rows [y, y + height).
struct Rect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;

  bool empty() const { return width <= 0 || height <= 0; }
  int right() const { return x + width; }    // one past the last column
  int bottom() const { return y + height; }  // one past the last row
  friend bool operator==(const Rect& a, const Rect& b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
  }
};

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
