// ObjectFinder's starts from the user's point or box: the candidates around the point, and
// which of them is the object.
#include <algorithm>
#include <cmath>
#include <optional>

#include "acquisition/object_finder.hpp"
#include "acquisition/separation.hpp"
#include "core/plausibility.hpp"

namespace projtrack {

bool ObjectFinder::nearest_apart_region(Point2i seed, const FinderParams& p, Mask& out) {
  const int w = candidates_.rect().width, h = candidates_.rect().height;
  // The seed's own pixel, or the nearest candidate pixel within a twentieth of the frame.
  const int reach = std::max(4, std::min(w, h) / 20);
  std::optional<Point2i> start;
  for (int r = 0; r <= reach && !start; ++r) {
    for (int dy = -r; dy <= r && !start; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
        const Point2i q{seed.x + dx, seed.y + dy};
        if (candidates_.at(q)) {
          start = q;
          break;
        }
      }
    }
  }
  if (!start) return false;
  regions_.label(candidates_.view(), false);
  int label = regions_.row(start->y)[start->x];
  // A region smaller than any the finder takes for an object (a detail of a print under the
  // user's point), inside a larger one (the print's frame around it): the object is the larger
  // one, holes and all.
  if (regions_.size(label) < p.min_area * w * h) {
    if (const int outer = enclosing_region(*start, label, p.min_area * w * h)) label = outer;
  }
  copy_region(label, out);
  return true;
}

void ObjectFinder::clip_to(const Rect& box, Mask& m) {
  for (int y = 0; y < m.rect().height; ++y)
    for (int x = 0; x < m.rect().width; ++x)
      if (!box.contains({x + m.rect().x, y + m.rect().y})) m.row(y)[x] = 0;
  m.crop();
}

namespace {

// A region's colour separation from its ring (1 − the Bhattacharyya coefficient) above which its
// colours are more unlike its surroundings' than like them.
constexpr double kStandsApart = 0.5;

}  // namespace

bool ObjectFinder::around_point(const Mask& region, Point2i p) {
  // A point is an instruction: a region found beside it (the nearest one apart from the border,
  // when the point's own colour is the border's) may be something beside the object under the
  // point; one around the point holds it within its convex hull (a print at the object's outline
  // cuts a notch into it).
  ops_.convex_hull(region, enclosure_);
  return enclosure_.at(p);
}

bool ObjectFinder::around_seed(Point2i seed_pixel, const FinderParams& p, const Rect* box,
                               Mask& out, std::string& why) {
  foreground(p);
  const int w = candidates_.rect().width, h = candidates_.rect().height, s = work_.scale();
  const Point2i seed{seed_pixel.x / std::max(1, s), seed_pixel.y / std::max(1, s)};
  if (seed_pixel.x < 0 || seed_pixel.y < 0 || seed.x >= w || seed.y >= h) {
    why = "the inner point lies outside the frame";
    return false;
  }
  // The user's object may fill most of the picture (kUserMaxArea), never all of it.
  const double most = kUserMaxArea * w * h;
  bool apart = nearest_apart_region(seed, p, out) && moments(out).area <= most;
  if (apart && box) clip_to(*box, out);
  apart_from_border_ = apart;
  // The border shows the seed's own colour: the region of that colour around the seed is a
  // candidate too. Within the user's box, the one that fills more of it is the object; else the
  // one whose colours stand further apart from its surroundings' (a white disc on a black
  // target, before a wall as white: the disc, not the target).
  if (candidates_.at(seed) ||
      !seed_region_.grow(work_.view(), {0, 0}, seed, 1, most, by_colour_, ops_)) {
    if (!apart)
      why =
          "no region around the inner point: neither its own colour nor one the frame's "
          "border does not show";
    return apart;
  }
  if (box) clip_to(*box, by_colour_);
  bool by_colour = !apart || (box && moments(by_colour_).area > moments(out).area);
  if (apart && !box) {
    const double own = colour_separation(work_.view(), by_colour_, ops_, enclosure_);
    // A region beside the point gives way to the point's own when that one stands apart from
    // its surroundings (its colours more unlike its ring's than like them); one around the point
    // to the one that stands further apart.
    by_colour = around_point(out, seed)
                    ? own > colour_separation(work_.view(), out, ops_, enclosure_)
                    : own > kStandsApart;
  }
  if (by_colour) {
    out.swap(by_colour_);
    apart_from_border_ = false;
  }
  return true;
}

bool ObjectFinder::from_seed(const ColorView& frame, Point2i seed_pixel, const FinderParams& p,
                             Mask& out, std::string& why) {
  load(frame, p, work_);
  return around_seed(seed_pixel, p, nullptr, out, why);
}

bool ObjectFinder::from_box(const ColorView& frame, const Rect& box, const FinderParams& p,
                            Mask& out, std::string& why) {
  const Rect b = clip_to_frame(box, frame.luma.width, frame.luma.height);
  if (b.empty()) {
    why = "the box lies outside the frame";
    return false;
  }
  load(frame, p, work_);
  const Rect wb = to_work(b, work_.scale());
  const Point2i centre{b.x + b.width / 2, b.y + b.height / 2};
  if (around_seed(centre, p, &wb, out, why) && !out.empty() &&
      moments(out).area >= 0.2 * wb.width * wb.height)
    return true;
  // Nothing of its own colours fills the box: the user's box is the object's outline.
  apart_from_border_ = true;  // its colours are learned against the border's (the box may be all)
  out.reset(wb & work_.rect());
  const double cx = wb.x + wb.width / 2.0 - 0.5, cy = wb.y + wb.height / 2.0 - 0.5;
  const double rx = wb.width / 2.0, ry = wb.height / 2.0;
  for (int y = 0; y < out.rect().height; ++y) {
    for (int x = 0; x < out.rect().width; ++x) {
      const double dx = (x + out.rect().x - cx) / rx, dy = (y + out.rect().y - cy) / ry;
      out.row(y)[x] = dx * dx + dy * dy <= 1.0;
    }
  }
  out.crop();
  why.clear();
  return !out.empty();
}

}  // namespace projtrack
