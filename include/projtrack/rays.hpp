// Ray casting on an edge map: the primitive of the four ray methods and of the inner-point update.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry.hpp"
#include "image_view.hpp"
#include "work_budget.hpp"

namespace projtrack {

// Work counters, reported in Features, and what the work costs a budget (work_budget.hpp).
struct Work {
  std::uint64_t rays = 0;
  std::uint64_t pixels = 0;
  BoundsAccumulator reach;  // every ray's last free pixel: where the rays read up to

  // Budget units: the rays and pixels above, each weighted by what its kind costs, and what else
  // the estimate did (clearing its masks, looking for a free pixel).
  std::uint64_t cost = 0;
  WorkBudget* budget = nullptr;  // none: unlimited, never stopped
  bool stopped = false;          // a checkpoint said stop: the estimate unwinds, its result void

  // The checkpoint, polled between coarse steps (a ray, a fill's run, a grid line, an iteration):
  // true once the estimate must stop (the budget would be passed, or the stop flag is set).
  bool must_stop() {
    if (!stopped && budget && budget->exhausted(cost)) stopped = true;
    return stopped;
  }
  // A fill read and marked `n` pixels of a row.
  void fill(std::uint64_t n) {
    pixels += n;
    cost += n;
  }
  // A ray or a walk stepped through `n` pixels.
  void steps(std::uint64_t n) {
    pixels += n;
    cost += n * kCostPerRayStep;
  }
};

struct RayHit {
  Point2i last_free;  // the last free pixel on the ray (the origin if it is blocked at once)
  Point2d hit;        // where it met the edge or the frame border: half a step past last_free
  int length = 0;     // pixels stepped from the origin
  bool at_border = false;
};

// n directions evenly spread in angle, the first along +x. A ray steps one pixel at a time along
// its major axis (DDA, 16.16 fixed point) and stops at the first edge pixel or the frame border.
// A diagonal step between two edge pixels also stops it: like a 4-connected fill, a ray cannot
// slip through an 8-connected edge line (Canny's lines are 8-connected).
class RayFan {
 public:
  void set_count(int n);
  int count() const { return static_cast<int>(dirs_.size()); }

  // Casts ray k from `origin` (a free pixel inside `edges`), calling visit(x, y) on every free
  // pixel it runs through, the origin included.
  template <class Visit>
  RayHit cast(const ImageView& edges, Point2i origin, int k, Visit&& visit) const;
  RayHit cast(const ImageView& edges, Point2i origin, int k) const {
    return cast(edges, origin, k, [](int, int) {});
  }

 private:
  struct Dir {
    std::int64_t sx, sy;  // one step, 16.16 fixed point; the major axis steps exactly 1 px
    double hx, hy;        // half a step, px
  };
  std::vector<Dir> dirs_;
};

// Casts the whole fan from `origin`, appending the hits to `hits`; returns the mean hit point.
// Stops between rays when work.must_stop(): then `hits` holds fewer than the fan's rays.
Point2d cast_fan(const ImageView& edges, Point2i origin, const RayFan& fan,
                 std::vector<RayHit>& hits, Work& work);

// Area of the star polygon through `count` hits cast in angle order from one origin, px².
double fan_area(const RayHit* hits, int count, Point2i origin);

template <class Visit>
RayHit RayFan::cast(const ImageView& edges, Point2i origin, int k, Visit&& visit) const {
  const Dir& d = dirs_[k];
  std::int64_t fx = static_cast<std::int64_t>(origin.x) << 16;
  std::int64_t fy = static_cast<std::int64_t>(origin.y) << 16;
  int x = origin.x, y = origin.y;
  RayHit r;
  visit(x, y);
  for (;;) {
    fx += d.sx;
    fy += d.sy;
    const int nx = static_cast<int>((fx + 0x8000) >> 16);
    const int ny = static_cast<int>((fy + 0x8000) >> 16);
    if (!edges.contains(nx, ny)) {
      r.at_border = true;
      break;
    }
    if (edges.at(nx, ny) != 0) break;
    if (nx != x && ny != y && edges.at(nx, y) != 0 && edges.at(x, ny) != 0) break;
    x = nx;
    y = ny;
    ++r.length;
    visit(x, y);
  }
  r.last_free = {x, y};
  r.hit = {x + d.hx, y + d.hy};
  return r;
}

}  // namespace projtrack
