#include "object_model.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

// `src` copied into a mask covering `r` (what lies outside r is dropped, what r adds is unset).
void embed(const Mask& src, const Rect& r, Mask& dst) {
  dst.reset(r);
  const Rect common = src.rect() & r;
  for (int y = common.y; y < common.bottom(); ++y)
    std::copy_n(src.row(y - src.rect().y) + (common.x - src.rect().x), common.width,
                dst.row(y - r.y) + (common.x - r.x));
}

Rect grown(const Rect& r, int by, const ImageView& frame) {
  return clip_to_frame({r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by}, frame.width,
                       frame.height);
}

int at_least(double share, double area, int floor) {
  return std::max(floor, static_cast<int>(std::lround(share * std::sqrt(std::max(area, 0.0)))));
}

// How far `p` lies inside `m`: the Chebyshev distance to the nearest unset pixel (or outside).
int depth_at(const Mask& m, Point2i p, int limit) {
  for (int r = 1; r <= limit; ++r) {
    for (int d = -r; d <= r; ++d) {
      if (!m.at({p.x + d, p.y - r}) || !m.at({p.x + d, p.y + r}) || !m.at({p.x - r, p.y + d}) ||
          !m.at({p.x + r, p.y + d}))
        return r;
    }
  }
  return limit;
}

}  // namespace

void ObjectModel::reset() {
  appearance_.reset();
  silhouette_.reset({});
}

void ObjectModel::learn(const ColorView& frame, const Mask& object, const Mask& silhouette,
                        double ring, double rate) {
  const int width = at_least(ring, moments(silhouette).area, 8);
  embed(silhouette, grown(silhouette.rect(), width, frame.luma), grown_);
  ops_.dilate(grown_, width, ring_);
  for (int y = 0; y < ring_.rect().height; ++y) {
    std::uint8_t* r = ring_.row(y);
    const std::uint8_t* s = grown_.row(y);
    for (int x = 0; x < ring_.rect().width; ++x) r[x] &= !s[x];
  }
  appearance_.learn(frame, object, ring_, rate);
}

bool ObjectModel::segment(const ColorView& frame, EdgeSource& edges, const Rect& roi,
                          const Mask& prior, double area, Point2i hint, int reach,
                          const ObjectModelParams& p, Mask& out) {
  const ImageView e = edges.region(roi);
  appearance_.likelihood(frame, roi, likelihood_);
  SilhouetteParams sp;
  sp.reach = reach;
  sp.small_region = p.small_region;
  return segmenter_.segment(likelihood_, e, roi, prior, area, hint, sp, out) &&
         moments(out).area > 0;
}

void ObjectModel::take_unseen_inside(const ColorView& frame, Point2i seed, Mask& s) {
  // The core's colours are not all the object's (a print elsewhere on it): a colour the model
  // has not seen at all, within the convex hull of what the core's colours found, is the
  // object's too. What sticks out of that hull (the hand that holds the object) is not taken.
  ops_.convex_hull(s, grown_);
  const Rect& r = s.rect();
  appearance_.seen(frame, r, likelihood_);
  for (int y = 0; y < r.height; ++y) {
    std::uint8_t* o = s.row(y);
    const std::uint8_t* hull = grown_.row(y);
    const std::uint8_t* known = likelihood_.data() + static_cast<std::size_t>(y) * r.width;
    for (int x = 0; x < r.width; ++x)
      if (hull[x] && !known[x]) o[x] = 1;
  }
  if (!ops_.keep_component(s, seed)) ops_.keep_component(s, ops_.deepest(s).first);
  ops_.fill_holes(s);
}

bool ObjectModel::start(const ColorView& frame, EdgeSource& edges, const Mask& first, Point2i seed,
                        const ObjectModelParams& p, Mask& out) {
  const MaskMoments m0 = moments(first);
  if (m0.area <= 0) return false;
  if (!first.at(seed)) seed = ops_.deepest(first).first;
  const int radius = std::max(depth_at(first, seed, first.rect().width + first.rect().height),
                              at_least(p.core, m0.area, 1));
  embed(first, first.rect(), core_);
  for (int y = 0; y < core_.rect().height; ++y) {
    std::uint8_t* c = core_.row(y);
    const long long dy = y + core_.rect().y - seed.y;
    for (int x = 0; x < core_.rect().width; ++x) {
      const long long dx = x + core_.rect().x - seed.x;
      if (dx * dx + dy * dy > 1LL * radius * radius) c[x] = 0;
    }
  }
  // The first silhouette's concavities may be the object's parts the border rule left out:
  // they are not its surroundings either.
  ops_.convex_hull(first, prior_);
  learn(frame, core_, prior_, p.ring, 1.0);
  embed(first, first.rect(), prior_);
  for (int round = 0; round < std::max(1, p.start_rounds); ++round) {
    const MaskMoments m = moments(prior_);
    // The first silhouette may be a fragment of the object: let it grow further than a frame's
    // motion would.
    const int reach = at_least(2 * p.reach, m.area, 8);
    const int margin =
        std::max(16, static_cast<int>(p.margin * std::max(m.bbox.width, m.bbox.height))) + reach;
    const Rect roi = grown(m.bbox, margin, frame.luma);
    if (!segment(frame, edges, roi, prior_, m.area, seed, reach, p, out)) return false;
    if (round == 0) take_unseen_inside(frame, seed, out);
    ops_.erode(out, 2, core_);
    learn(frame, moments(core_).area > 0 ? core_ : out, out, p.ring, 1.0);
    embed(out, out.rect(), prior_);
  }
  embed(out, out.rect(), silhouette_);
  return true;
}

bool ObjectModel::resume(const ColorView& frame, EdgeSource& edges, const Mask& first, Point2i seed,
                         const ObjectModelParams& p, Mask& out) {
  const MaskMoments m = moments(first);
  if (m.area <= 0 || !knows_colours()) return false;
  const int reach = at_least(2 * p.reach, m.area, 8);
  const int margin =
      std::max(16, static_cast<int>(p.margin * std::max(m.bbox.width, m.bbox.height))) + reach;
  if (!segment(frame, edges, grown(m.bbox, margin, frame.luma), first, m.area, seed, reach, p, out))
    return false;
  embed(out, out.rect(), silhouette_);
  return true;
}

bool ObjectModel::find(const ColorView& frame, EdgeSource& edges, Point2d motion, Point2i hint,
                       const ObjectModelParams& p, Mask& out) {
  if (!tracking()) return false;
  const MaskMoments m = moments(silhouette_);
  embed(silhouette_, silhouette_.rect(), prior_);
  const Point2i shift = round_to_pixel(motion);
  prior_.translate(shift.x, shift.y);
  const Rect box{m.bbox.x + shift.x, m.bbox.y + shift.y, m.bbox.width, m.bbox.height};
  const int reach = at_least(p.reach, m.area, 8);
  int margin = std::max(16, static_cast<int>(p.margin * std::max(box.width, box.height))) + reach;
  for (int attempt = 0;; ++attempt) {
    const Rect roi = grown(box, margin, frame.luma);
    if (roi.empty() || !segment(frame, edges, roi, prior_, m.area, hint, reach, p, out))
      return false;
    // A silhouette that reaches the region's border (where it is not the frame's) was cut by
    // it: search once more in a region twice as wide.
    const Rect b = moments(out).bbox;
    const bool cut = (b.x == roi.x && roi.x > 0) || (b.y == roi.y && roi.y > 0) ||
                     (b.right() == roi.right() && roi.right() < frame.luma.width) ||
                     (b.bottom() == roi.bottom() && roi.bottom() < frame.luma.height);
    if (!cut || attempt == 1) return true;
    margin *= 2;
  }
}

void ObjectModel::accept(const ColorView& frame, const Mask& s, const ObjectModelParams& p) {
  ops_.erode(s, 2, core_);
  learn(frame, moments(core_).area > 0 ? core_ : s, s, p.ring, p.learning_rate);
  embed(s, s.rect(), silhouette_);
}

}  // namespace projtrack
