#include "appearance/silhouette_model.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

Rect grown(const Rect& r, int by) {
  return {r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by};
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

int margin_for(const MaskMoments& m, int reach, const ObjectModelParams& p) {
  return std::max(4, static_cast<int>(p.margin * std::max(m.bbox.width, m.bbox.height))) + reach;
}

// Whether box `b` reaches the border of `frame` (a silhouette along the arm that holds it).
bool reaches_border(const Rect& b, const Rect& frame) {
  return !b.empty() && (b.x <= frame.x || b.y <= frame.y || b.right() >= frame.right() ||
                        b.bottom() >= frame.bottom());
}

}  // namespace

void SilhouetteModel::forget() {
  appearance_.reset();
  silhouette_.reset({});
}

void SilhouetteModel::rescale(double sx, double sy) {
  if (!(sx > 0 && sy > 0 && std::isfinite(sx) && std::isfinite(sy))) return;
  // As many work pixels as before: the object's size in them is what its parameters are for.
  const double to = std::round(scale_ * std::sqrt(sx * sy));
  const int scale = static_cast<int>(std::clamp(to, 1.0, 1e6));
  if (tracking()) {
    resample(silhouette_, scale_, sx, sy, scale, prior_);
    silhouette_.swap(prior_);
    if (moments(silhouette_).area <= 0) silhouette_.reset({});
  }
  scale_ = scale;
}

Point2i SilhouetteModel::to_work(Point2i p) const {
  const auto down = [&](int v) { return v >= 0 ? v / scale_ : -((-v + scale_ - 1) / scale_); };
  return {down(p.x), down(p.y)};
}

void SilhouetteModel::load(const ColorView& frame, const Rect& box, int margin, double area,
                           bool learning, const ObjectModelParams& p) {
  const int ring = learning ? at_least(p.ring, area, 3) : 0;
  work_.build(frame, scale_, grown(box, std::max(margin, ring)));
  score();
}

void SilhouetteModel::score() {
  const Rect& roi = work_.rect();
  appearance_.likelihood(work_.view(), {roi.x, roi.y}, roi, likelihood_);
}

void SilhouetteModel::recentre(Mask& prior, int window) {
  // Mean shift on the likelihood, as CamShift does: the prior moves to the centre of the
  // object-like pixels around it, a few times, so that an object faster than its predicted
  // motion is not cut where the prior ends.
  const Rect& roi = work_.rect();
  for (int iteration = 0; iteration < 3; ++iteration) {
    const MaskMoments m = moments(prior);
    const Rect w = grown(m.bbox, window) & roi;
    double mass = 0, sx = 0, sy = 0;
    for (int y = w.y; y < w.bottom(); ++y) {
      const std::uint8_t* l =
          likelihood_.data() + static_cast<std::size_t>(y - roi.y) * roi.width - roi.x;
      for (int x = w.x; x < w.right(); ++x) {
        if (l[x] < 128) continue;
        mass += 1;
        sx += x;
        sy += y;
      }
    }
    if (mass < 0.3 * m.area) return;  // too little of the object around: leave the prior be
    const Point2i d = round_to_pixel({sx / mass - m.centroid.x, sy / mass - m.centroid.y});
    if (d.x == 0 && d.y == 0) return;
    prior.translate(d.x, d.y);
  }
}

namespace {

// How wide, in frame px, the band along an outline where the object's colours mix with what is
// behind it: one chroma sample (chroma is sampled at half resolution), blur within it.
constexpr int kMixedOutline = 2;

}  // namespace

void SilhouetteModel::learn(const Mask& object, const Mask& silhouette, double ring, double rate,
                            bool past_outline) {
  // The ring starts at the silhouette's convex hull: what the silhouette missed in its
  // concavities (a print at its outline, a shadowed part) may be the object's and must not be
  // learned as its surroundings. Past a segmented silhouette's outline it starts beyond the band
  // of mixed colours: learned as the surroundings, they would hold every next silhouette a band
  // inside the last one (a small ball shrinks to its bright core). A first region from the
  // finder keeps its outline's pixels in the ring: they are what the arm cut tells an arm by.
  const int width = at_least(ring, moments(silhouette).area, 3);
  ops_.convex_hull(silhouette, hull_);
  const int gap = past_outline ? (kMixedOutline + scale_ - 1) / scale_ : 0;
  embed(hull_, grown(silhouette.rect(), width + gap) & work_.rect(), grown_);
  if (gap > 0) {
    ops_.dilate(grown_, gap, hull_);
    grown_.swap(hull_);
  }
  ops_.dilate(grown_, width, ring_);
  for (int y = 0; y < ring_.rect().height; ++y) {
    std::uint8_t* r = ring_.row(y);
    const std::uint8_t* s = grown_.row(y);
    for (int x = 0; x < ring_.rect().width; ++x) r[x] &= !s[x];
  }
  appearance_.learn(work_.view(), {work_.rect().x, work_.rect().y}, object, ring_, rate);
}

bool SilhouetteModel::segment(EdgeSource& edges, const Mask& prior, double area, Point2i hint,
                              int reach, const ObjectModelParams& p, Mask& out, bool first) {
  const Rect& roi = work_.rect();
  const ImageView e = edges.work(work_, edge_map_, edge_buffer_);
  SilhouetteParams sp;
  sp.reach = reach;
  sp.small_region = p.small_region;
  sp.all_pieces_in_reach = first;
  return segmenter_.segment(likelihood_, e, roi, prior, area, hint, sp, out) &&
         moments(out).area > 0;
}

void SilhouetteModel::take_unknown_inside(Point2i seed, Mask& s) {
  // The core's colours are not all the object's (a print elsewhere on it): a colour not seen
  // more around the object than on it, within the convex hull of what the core's colours found,
  // is the object's too. What sticks out of that hull (the hand that holds the object) is not.
  ops_.convex_hull(s, grown_);
  const Rect& r = s.rect();
  appearance_.surroundings_like(work_.view(), {work_.rect().x, work_.rect().y}, r, likelihood_);
  for (int y = 0; y < r.height; ++y) {
    std::uint8_t* o = s.row(y);
    const std::uint8_t* hull = grown_.row(y);
    const std::uint8_t* around = likelihood_.data() + static_cast<std::size_t>(y) * r.width;
    for (int x = 0; x < r.width; ++x)
      if (hull[x] && !around[x]) o[x] = 1;
  }
  if (!ops_.keep_component(s, seed)) ops_.keep_component(s, ops_.deepest(s).first);
  ops_.fill_holes(s);
}

void SilhouetteModel::cut_arm(Mask& s, const Mask& before, const Rect& frame, Point2i seed,
                              const ObjectModelParams& p) {
  const MaskMoments m = moments(s);
  const Rect& b = m.bbox;
  if (!(p.arm_cut > 0) || !reaches_border(b, frame)) return;
  const int r = at_least(p.arm_cut, m.area, 1);
  ops_.erode(s, r, hull_);
  if (moments(hull_).area <= 0) return;  // all of it thin: nothing to tell the arm by
  ops_.dilate(hull_, r, grown_);
  const Rect& g = grown_.rect();
  for (int y = 0; y < g.height; ++y) {  // the opening, within the silhouette
    std::uint8_t* o = grown_.row(y);
    for (int x = 0; x < g.width; ++x) o[x] = o[x] && s.at({x + g.x, y + g.y});
  }
  pieces_.label(grown_.view(), false);
  const std::int32_t seed_piece = g.contains(seed) ? pieces_.row(seed.y - g.y)[seed.x - g.x] : 0;
  // A piece is the arm when it reaches the frame's border and most of it is new: an object cut
  // by the frame's edge was there before, an arm that grew along the hand was not.
  const std::size_t n = static_cast<std::size_t>(pieces_.count()) + 1;
  arm_.assign(n, 0);
  piece_before_.assign(n, 0);
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const std::int32_t l = pieces_.row(y)[x];
      if (!l) continue;
      const int fx = x + g.x, fy = y + g.y;
      piece_before_[l] += before.at({fx, fy});
      if (l != seed_piece &&
          (fx <= frame.x || fy <= frame.y || fx >= frame.right() - 1 || fy >= frame.bottom() - 1))
        arm_[static_cast<std::size_t>(l)] = 1;
    }
  for (std::size_t l = 1; l < n; ++l)
    arm_[l] = arm_[l] && 2 * piece_before_[l] < pieces_.size(static_cast<int>(l));
  for (int y = 0; y < g.height; ++y) {
    std::uint8_t* o = grown_.row(y);
    for (int x = 0; x < g.width; ++x)
      o[x] = o[x] && !arm_[static_cast<std::size_t>(pieces_.row(y)[x])];
  }
  if (moments(grown_).area <= 0) return;
  embed(grown_, s.rect(), s);
  ops_.fill_holes(s);
}

bool SilhouetteModel::start(const ColorView& frame, EdgeSource& edges, const Mask& first,
                            int first_scale, Point2i seed_pixel,
                            const std::vector<std::uint32_t>& background, const Rect& bound,
                            const ObjectModelParams& p, Mask& out) {
  const double frame_area = moments(first).area * first_scale * first_scale;
  if (frame_area <= 0) return false;
  scale_ = work_scale(frame_area, p.work_pixels);
  projtrack::rescale(first, first_scale, scale_, prior_);
  const MaskMoments m0 = moments(prior_);
  if (m0.area <= 0) return false;
  Point2i seed = to_work(seed_pixel);
  if (!prior_.at(seed)) seed = ops_.deepest(prior_).first;
  const int reach = at_least(p.start_reach, m0.area, 2);
  load(frame, m0.bbox, margin_for(m0, reach, p), m0.area, true, p);
  unlearned_ = 0;
  const Rect whole{0, 0, (frame.luma.width + scale_ - 1) / scale_,
                   (frame.luma.height + scale_ - 1) / scale_};
  // The core: the disc around the seed, within the first silhouette.
  const int radius = std::max(depth_at(prior_, seed, prior_.rect().width + prior_.rect().height),
                              at_least(p.core, m0.area, 1));
  embed(prior_, prior_.rect(), core_);
  for (int y = 0; y < core_.rect().height; ++y) {
    std::uint8_t* c = core_.row(y);
    const long long dy = y + core_.rect().y - seed.y;
    for (int x = 0; x < core_.rect().width; ++x) {
      const long long dx = x + core_.rect().x - seed.x;
      if (dx * dx + dy * dy > 1LL * radius * radius) c[x] = 0;
    }
  }
  // Against the border's colours, not a ring: a ring could hold the object's own part beyond a
  // finger across it. Without them (the border shows the object's colours too), against a ring
  // around the first silhouette.
  if (background.empty())
    learn(core_, prior_, p.ring, 1.0, false);
  else
    appearance_.learn(work_.view(), {work_.rect().x, work_.rect().y}, core_, background);
  score();
  // Rounds of segmenting and learning, at least start_rounds, and on while the silhouette grows
  // (the part of the object beyond a finger comes in a reach at a time), at most three times as
  // many.
  const int rounds = std::max(1, p.start_rounds);
  for (int round = 0; round < 3 * rounds; ++round) {
    const MaskMoments m = moments(prior_);
    const int reach = at_least(p.start_reach, m.area, 2);
    if (round > 0) load(frame, m.bbox, margin_for(m, reach, p), m.area, true, p);
    if (!segment(edges, prior_, m.area, seed, reach, p, out, true)) {
      silhouette_.reset({});
      return false;
    }
    if (round == 0) take_unknown_inside(seed, out);
    cut_arm(out, prior_, whole, seed, p);
    if (!bound.empty()) {
      embed(out, out.rect() & projtrack::to_work(bound, scale_), grown_);
      out.swap(grown_);
      if (moments(out).area <= 0) break;
    }
    learn(learning_core(out, p), out, p.ring, 1.0, true);
    score();
    const bool grew = moments(out).area > 1.02 * m.area;
    embed(out, out.rect(), prior_);
    if (round + 1 >= rounds && !grew) break;
  }
  embed(out, out.rect(), silhouette_);
  return true;
}

bool SilhouetteModel::resume(const ColorView& frame, EdgeSource& edges, const Mask& first,
                             int first_scale, Point2i seed_pixel, const ObjectModelParams& p,
                             Mask& out) {
  const double frame_area = moments(first).area * first_scale * first_scale;
  if (frame_area <= 0 || !knows_colours()) return false;
  scale_ = work_scale(frame_area, p.work_pixels);
  projtrack::rescale(first, first_scale, scale_, prior_);
  const MaskMoments m = moments(prior_);
  const int reach = at_least(2 * p.reach, m.area, 2);
  load(frame, m.bbox, margin_for(m, reach, p), m.area, true, p);
  unlearned_ = std::max(0, p.learn_every - 1);  // learn on the first accepted frame
  if (!segment(edges, prior_, m.area, to_work(seed_pixel), reach, p, out)) return false;
  embed(out, out.rect(), silhouette_);
  return true;
}

bool SilhouetteModel::find(const ColorView& frame, EdgeSource& edges, Point2d motion, Point2i hint,
                           const ObjectModelParams& p, Mask& out) {
  if (!tracking()) return false;
  const MaskMoments m = moments(silhouette_);
  embed(silhouette_, silhouette_.rect(), prior_);
  const Point2i shift = round_to_pixel({motion.x / scale_, motion.y / scale_});
  prior_.translate(shift.x, shift.y);
  const int reach = at_least(p.reach, m.area, 2), window = at_least(p.window, m.area, 2);
  // The silhouette lies within reach of the prior, which the mean shift moves by up to a window:
  // the edges must be right there, a guard band beyond (the blur's and Canny's neighbourhoods).
  int margin = reach + window + edges.border_guard();
  const Rect frame_work = {0, 0, (frame.luma.width + scale_ - 1) / scale_,
                           (frame.luma.height + scale_ - 1) / scale_};
  const bool learning = unlearned_ + 1 >= p.learn_every;
  for (int attempt = 0;; ++attempt) {
    // First around the predicted box, then in a region twice as wide, then the whole frame.
    const MaskMoments pm = moments(prior_);
    if (attempt < 2)
      load(frame, pm.bbox, margin, m.area, learning, p);
    else
      load(frame, frame_work, 0, m.area, learning, p);
    if (work_.rect().empty()) return false;
    recentre(prior_, window);
    if (!segment(edges, prior_, m.area, hint.x >= 0 ? to_work(hint) : hint, reach, p, out))
      return false;
    // An arm that grew out of the silhouette to the frame's border this frame goes now, before
    // it is learned (the deepest point of the prior, a distance transform, only then).
    MaskMoments om = moments(out);
    if (reaches_border(om.bbox, frame_work)) {
      cut_arm(out, prior_, frame_work, hint.x >= 0 ? to_work(hint) : ops_.deepest(prior_).first, p);
      om = moments(out);
    }
    if (om.area <= 0) return false;
    // A silhouette that reaches the region's border (where it is not the frame's) was cut by
    // it: search again in a larger region.
    const Rect b = om.bbox, roi = work_.rect();
    const bool cut = (b.x == roi.x && roi.x > 0) || (b.y == roi.y && roi.y > 0) ||
                     (b.right() == roi.right() && roi.right() < frame_work.width) ||
                     (b.bottom() == roi.bottom() && roi.bottom() < frame_work.height);
    if (!cut || attempt == 2) return true;
    margin *= 2;
  }
}

const Mask& SilhouetteModel::learning_core(const Mask& s, const ObjectModelParams& p) {
  const int r = at_least(p.arm_cut, moments(s).area, 1);
  ops_.erode(s, r, core_);
  if (r > 1 && moments(core_).area > 0) {
    ops_.dilate(core_, r, hull_);  // the opening: where the silhouette is thicker than an arm
    embed(hull_, s.rect(), grown_);
    for (int y = 0; y < grown_.rect().height; ++y) {
      std::uint8_t* g = grown_.row(y);
      const std::uint8_t* o = s.row(y);
      for (int x = 0; x < grown_.rect().width; ++x) g[x] &= o[x];
    }
    ops_.erode(grown_, 1, core_);
    if (moments(core_).area > 0) return core_;
  }
  ops_.erode(s, 1, core_);  // no thick part: all of it, less its outline
  return moments(core_).area > 0 ? core_ : s;
}

void SilhouetteModel::accept(const Mask& s, const ObjectModelParams& p) {
  const int every = std::max(1, p.learn_every);
  if (++unlearned_ >= every) {
    // As many frames' worth of learning at once: 1 - (1 - rate)^every.
    const double rate = 1 - std::pow(1 - std::clamp(p.learning_rate, 0.0, 1.0), every);
    ops_.erode(s, 1, core_);
    learn(moments(core_).area > 0 ? core_ : s, s, p.ring, rate, true);
    unlearned_ = 0;
  }
  embed(s, s.rect(), silhouette_);
}

}  // namespace projtrack
