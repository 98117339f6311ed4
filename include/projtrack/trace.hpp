// An optional record of what an estimator did, for overlays and the paper's figures.
#pragma once

#include <vector>

#include "geometry.hpp"

namespace projtrack {

// Pass a Trace to Estimator::estimate() to get it filled; pass none and nothing is recorded.
// The vectors keep their capacity across frames, so a reused Trace does not allocate per frame.
// Rays are recorded up to kMaxRays (n^y methods can cast millions); later ones are only counted.
struct Trace {
  static constexpr std::size_t kMaxRays = 1 << 17;

  struct Ray {
    Point2d origin;
    Point2d hit;    // where it met an edge or the frame border
    int iteration;  // 1-based; 0 for the rays of inner-point updates
    int level;      // 1 for rays from the inner point, 2.. for recast rays (n^y methods)
  };
  struct Block {
    Rect rect;      // an m×m block selected by rasterization (clipped to the frame)
    int iteration;  // when it was first selected
  };
  struct Run {
    Point2i first;  // a horizontal or vertical run of filled pixels, both ends included
    Point2i last;
  };
  struct Iteration {
    Point2i inner_point;  // where this iteration cast from
    Point2d centroid;
    double area;  // px², when the method estimates one per iteration (else 0)
  };

  std::vector<Ray> rays;
  std::size_t rays_not_recorded = 0;
  std::vector<Block> blocks;
  std::vector<Run> runs;  // pixel-filling: row runs; grid-filling: grid-line runs
  std::vector<Iteration> iterations;
  // The object's silhouette outline, in frame coordinates, when the tracker found one (the flow
  // model); translate() leaves it alone.
  std::vector<Point2i> outline;

  void add_ray(const Ray& r) {
    if (rays.size() < kMaxRays)
      rays.push_back(r);
    else
      ++rays_not_recorded;
  }
  // The last iteration whose rays were recorded (0 when none were).
  int last_recorded_iteration() const {
    int last = 0;
    for (const Ray& r : rays) last = r.iteration > last ? r.iteration : last;
    return last;
  }

  // Moves everything recorded in a region of the frame into frame coordinates.
  void translate(int dx, int dy) {
    for (Ray& r : rays) {
      r.origin.x += dx, r.origin.y += dy;
      r.hit.x += dx, r.hit.y += dy;
    }
    for (Block& b : blocks) b.rect.x += dx, b.rect.y += dy;
    for (Run& r : runs) {
      r.first.x += dx, r.first.y += dy;
      r.last.x += dx, r.last.y += dy;
    }
    for (Iteration& i : iterations) {
      i.inner_point.x += dx, i.inner_point.y += dy;
      i.centroid.x += dx, i.centroid.y += dy;
    }
  }

  // Adds what `other` recorded (another estimate on the same frame).
  void append(const Trace& other) {
    for (const Ray& r : other.rays) add_ray(r);
    rays_not_recorded += other.rays_not_recorded;
    blocks.insert(blocks.end(), other.blocks.begin(), other.blocks.end());
    runs.insert(runs.end(), other.runs.begin(), other.runs.end());
    iterations.insert(iterations.end(), other.iterations.begin(), other.iterations.end());
  }

  void clear() {
    rays_not_recorded = 0;
    rays.clear();
    blocks.clear();
    runs.clear();
    iterations.clear();
    outline.clear();
  }
};

}  // namespace projtrack
