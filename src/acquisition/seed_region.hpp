// The region a user's point picks by its own colour: grown from the point as far as colours like
// its own reach, with the tolerance at which that region is most stable (a maximally stable
// region, Matas et al., BMVC 2002). The tolerance is the scene's and the object's: a white disc on
// a black target stays the disc over almost every tolerance, whatever else is white in the frame.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mask.hpp"
#include "projtrack/color_view.hpp"

namespace projtrack {

class SeedRegion {
 public:
  // The region of `frame` (a work frame, pixel (x, y) at work coordinates (x + origin.x, y +
  // origin.y)) around `seed` (work coordinates), into `out` with its holes filled: of the regions
  // grown at every tolerance, the most stable one of at least `least` and at most `most` pixels
  // that does not reach all four sides of the frame. False when there is none.
  bool grow(const ColorView& frame, Point2i origin, Point2i seed, double least, double most,
            Mask& out, MaskOps& ops);

 private:
  // The colour distance of every pixel to the seed's colour (the median of its 3×3 neighbours).
  void distances(const ColorView& frame, Point2i seed);
  // For every pixel, the least over 4-connected paths from the seed of the largest distance on
  // the path: the pixel joins the seed's region at that tolerance.
  void bottlenecks(int width, int height, Point2i seed);
  // The tolerance of the most stable region; -1 for none.
  int most_stable(int width, int height, double least, double most) const;

  // Both on the frame with a border of one pixel (row stride width + 2).
  std::vector<std::uint8_t> distance_;
  std::vector<std::uint16_t> bottleneck_;           // the tolerance each pixel joins at
  std::vector<std::vector<std::int32_t>> buckets_;  // pixels by tolerance (a bucket queue)
};

}  // namespace projtrack
