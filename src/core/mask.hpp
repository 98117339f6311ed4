// A binary mask over a rectangle of the frame, and the few operations the object model needs on
// it, all on buffers kept between frames.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "projtrack/geometry.hpp"
#include "projtrack/image_view.hpp"

namespace projtrack {

// Bytes 0 (out) or 1 (in) over rect(), in frame coordinates. Its buffer only grows: a mask that
// changes size from frame to frame allocates nothing once it has held its largest size.
class Mask {
 public:
  // Covers `r`, all zero.
  void reset(const Rect& r);
  const Rect& rect() const { return rect_; }
  bool empty() const { return rect_.empty(); }
  // Rows relative to rect(): row(0) is frame row rect().y.
  std::uint8_t* row(int y) { return data_.data() + static_cast<std::size_t>(y) * rect_.width; }
  const std::uint8_t* row(int y) const {
    return data_.data() + static_cast<std::size_t>(y) * rect_.width;
  }
  // Whether the frame pixel p is in the mask (false outside rect()).
  bool at(Point2i p) const { return rect_.contains(p) && row(p.y - rect_.y)[p.x - rect_.x] != 0; }
  ImageView view() const { return ImageView(data_.data(), rect_.width, rect_.height, rect_.width); }
  // Shrinks rect() to the box of the set pixels (empty when there are none).
  void crop();
  // Moves the mask by (dx, dy) in the frame, its pixels with it.
  void translate(int dx, int dy) {
    rect_.x += dx;
    rect_.y += dy;
  }
  void swap(Mask& other) {
    data_.swap(other.data_);
    std::swap(rect_, other.rect_);
  }

 private:
  Rect rect_;
  std::vector<std::uint8_t> data_;
};

// Area (px²), centroid and box of a mask's set pixels, in frame coordinates (area 0: none).
struct MaskMoments {
  double area = 0;
  Point2d centroid;
  Rect bbox;
};
MaskMoments moments(const Mask& m);

// `src` copied into a mask covering `r` (what lies outside r is dropped, what r adds is unset).
void embed(const Mask& src, const Rect& r, Mask& dst);

// `src`, a mask in work coordinates at scale `from` (see WorkFrame), at scale `to`: each pixel
// takes the value of the `from` pixel under its centre.
void rescale(const Mask& src, int from, int to, Mask& dst);

// `src`, a mask in work coordinates at scale `from` of a frame since resized by `sx` × `sy`, in
// work coordinates at scale `to` of the resized frame: each pixel takes the value of the `src`
// pixel under its centre.
void resample(const Mask& src, int from, double sx, double sy, int to, Mask& dst);

// The operations, with their scratch buffers (one instance per stream).
class MaskOps {
 public:
  // Sets every hole: each 0 pixel not 4-connected to the mask's border through 0 pixels.
  void fill_holes(Mask& m);
  // Keeps only the 4-connected component of set pixels that holds the frame pixel p; false (and
  // the mask unchanged) when p is not set.
  bool keep_component(Mask& m, Point2i p);
  // `dst` (on src's rectangle) = the pixels within Chebyshev distance r of a set pixel of `src`.
  void dilate(const Mask& src, int r, Mask& dst);
  // `dst` = the set pixels of `src` whose whole (2r+1)² square is set (outside counts as unset).
  // `dst` must not be `src` in either.
  void erode(const Mask& src, int r, Mask& dst);
  // The set pixel farthest from every unset pixel (and from outside the mask), in frame
  // coordinates, with that distance in px (chamfer 3-4, within 8 %); {} and 0 for an empty mask.
  std::pair<Point2i, double> deepest(const Mask& m);
  // `dst` (on src's rectangle) = the convex hull of the set pixels of `src` (their centres).
  void convex_hull(const Mask& src, Mask& dst);
  // Frame points of the set pixels with a 4-neighbour out of the mask: its outline.
  void outline(const Mask& m, std::vector<Point2i>& out) const;

 private:
  // Marks with `mark` the 4-connected run of pixels equal to `value` from p (mask coordinates).
  void flood(Mask& m, Point2i p, std::uint8_t value, std::uint8_t mark);
  // Dilation by r of the set pixels, or (invert) of the unset ones and the outside.
  void spread(const Mask& src, int r, bool invert, Mask& dst);
  std::vector<Point2i> stack_, points_, hull_;
  std::vector<int> counts_, distance_;
  std::vector<std::uint8_t> column_;
  Mask tmp_;
};

}  // namespace projtrack
