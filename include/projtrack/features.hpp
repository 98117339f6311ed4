// The one result type of every estimator.
#pragma once

#include <cstdint>
#include <string>

#include "geometry.hpp"
#include "status.hpp"

namespace projtrack {

struct Features {
  EstimateStatus status = EstimateStatus::EmptyImage;
  std::string detail;  // a human-readable reason when status has no features (else empty)

  // Valid when has_features(status):
  Point2d centroid;  // px, pixel centres at integer coordinates
  double area = 0;   // px², for every method (see docs/estimators.md for each mapping)
  Rect bbox;         // the pixels the estimate covers
  // The pixels the estimate and the inner-point update read, within a pixel: the box and every
  // ray's end. A caller that gave edges of a region checks this against the region's border.
  Rect reach;

  Point2i seed;                 // the free pixel the estimate started from (the inner point, or the
                                // nearest free pixel to it)
  Point2i inner_point;          // the updated inner point, for the next frame
  int iterations = 0;           // iterations used (1 for the non-iterative methods)
  std::uint64_t rays_cast = 0;  // work done: rays cast, inner-point updates included
  std::uint64_t pixels_visited = 0;  // work done: pixels tested by fills and ray steps

  bool valid() const { return has_features(status); }
};

}  // namespace projtrack
