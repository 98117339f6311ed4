#include "tracker/acquisition_policy.hpp"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <utility>

#include "acquisition/motion_gate.hpp"
#include "core/plausibility.hpp"

namespace projtrack {

namespace {

const std::vector<std::uint32_t> kNoColours;

// How much dimmer than TrackerParams::full_contrast the scene is: 1 at full contrast, at least ⅓.
double contrast(int spread, const TrackerParams& tp) {
  if (spread <= 0 || !(tp.full_contrast > 0)) return 1.0;
  return std::clamp(spread / tp.full_contrast, 1.0 / 3, 1.0);
}

// The share of the frame that must change before acquisition looks: TrackerParams::min_motion,
// or for an object lost before whose colours are known, a tenth of its own area if that is less
// (a small ball rolling moves far less of the frame than a held cup).
double least_motion(const TrackerState& s, const TrackerParams& tp, const ImageView& frame) {
  const double pixels = static_cast<double>(frame.width) * frame.height;
  if (!s.object.knows_colours() || !(s.track().lost_area > 0) || pixels <= 0) return tp.min_motion;
  return std::min(tp.min_motion, 0.1 * s.track().lost_area / pixels);
}

// Auto acquisition: an object lost before, by its colours (forgotten after
// TrackerParams::forget_after frames of search); else whatever moves. Needs the frame to move.
bool find_by_motion_or_colours(TrackerState& s, const ColorView& frame, const TrackerParams& tp,
                               const FinderParams& fp, Mask& first, Point2i& seed,
                               AppearanceStart& out) {
  const double gate = least_motion(s, tp, frame.luma);
  // The last frame that showed motion, for the finder's check that what moves now moved then
  // too (a frame repeated by the camera or the encoder shows none, and does not count).
  if (s.moved.fraction >= gate) std::swap(s.moved_before, s.moved);
  out.why =
      wait_for_motion(s.motion, frame.luma, motion_params(tp, s.motion.spread()), gate, s.moved);
  if (!out.why.empty()) return false;
  // A new object is what moves apart from the rest: changes spread evenly over the whole frame
  // (fresh noise, a flash) show none, and looking would read the whole frame for nothing. An
  // object whose colours are known is looked for still (sensor noise moves every part of the
  // frame, and the object with it).
  if (!s.object.knows_colours() && changed_evenly(s.moved, frame.luma.width, frame.luma.height)) {
    out.why = "the whole picture changed evenly: nothing moves apart from it";
    return false;
  }
  if (s.object.knows_colours() && s.track().searched >= tp.forget_after)
    s.forget_colours();  // not seen for long: look for any object
  s.count_search();
  if (s.object.knows_colours()) {
    out.resumed =
        s.finder.from_model(frame, s.object.appearance(), s.moved, s.track().lost_area,
                            tp.leak_factor, s.track().lost_centroid, fp, first, seed, out.why);
    return out.resumed;
  }
  if (s.finder.from_motion(frame, s.moved, s.moved_before, fp, first, seed, out.why)) return true;
  // No region of colours the border does not show moves: the moving object's colours are the
  // border's too (a dark puck on a table with dark edges); look where the frame moves.
  if (out.why != kNoMovingRegion) return false;
  return s.finder.from_moving_blob(frame, s.moved, s.moved_before, fp, first, seed, out.why);
}

// The finder's first silhouette, into `first`, and the point it grew from, into `seed`.
bool find_first_silhouette(TrackerState& s, const ColorView& frame, const TrackerParams& tp,
                           const FinderParams& fp, Mask& first, Point2i& seed,
                           AppearanceStart& out) {
  const int w = frame.luma.width, h = frame.luma.height;
  seed = {w / 2, h / 2};
  const TrackerState::Track& track = s.track();
  if (track.inner) {
    seed = *track.inner;
    if (!Rect{0, 0, w, h}.contains(seed)) {
      out.why = "the inner point lies outside the frame";
      return false;
    }
    return track.seed_box ? s.finder.from_box(frame, *track.seed_box, fp, first, out.why)
                          : s.finder.from_seed(frame, seed, fp, first, out.why);
  }
  if (tp.acquisition == Acquisition::Center) {
    const bool found = s.finder.from_seed(frame, seed, fp, first, out.why);
    if (!found) out.why = "at the frame centre: " + out.why;
    return found;
  }
  return find_by_motion_or_colours(s, frame, tp, fp, first, seed, out);
}

// Why an object found by motion alone is no start, if it is not one: a silhouette that grew from
// it to the frame's border has run into the arm that holds it (or the table); one that is the
// scene's background is a static region that a passer-by's colours joined.
std::string veto_motion_start(TrackerState& s, const ColorView& frame, const FinderParams& fp,
                              const Mask& silhouette) {
  const int w = frame.luma.width, h = frame.luma.height;
  const Rect b = to_frame(moments(silhouette).bbox, s.object.scale(), w, h);
  if (b.x <= 0 || b.y <= 0 || b.right() >= w || b.bottom() >= h)
    return "what moved there runs into the frame's border (an arm, not an object): left alone";
  if (s.finder.foreground_share(silhouette, s.object.scale(), fp) < fp.min_foreground)
    return "what moved there is the background (a static region): left alone";
  return {};
}

}  // namespace

MotionDetector::Params motion_params(const TrackerParams& tp, int spread) {
  MotionDetector::Params p = tp.motion;
  p.threshold = static_cast<int>(std::lround(p.threshold * contrast(spread, tp)));
  return p;
}

FinderParams finder_params(const TrackerParams& tp, int spread) {
  FinderParams p = tp.finder;
  p.background_change = static_cast<int>(std::lround(p.background_change * contrast(spread, tp)));
  return p;
}

std::optional<Features> start_edges_track(TrackerState& s, const ImageView& gray,
                                          const ImageView& edges, Estimator& est,
                                          const Params& params, double limit,
                                          const TrackerParams& tp, WorkBudget& budget,
                                          std::string& why) {
  s.edges_acquisition.use_mode(tp.acquisition);
  if (tp.acquisition == Acquisition::Manual) {
    why = kNoInnerPoint;
    return std::nullopt;
  }
  if (tp.acquisition == Acquisition::Center) {
    EstimateOptions options;
    options.budget = &budget;
    Features f = est.estimate(edges, {edges.width / 2, edges.height / 2}, params, options);
    why = why_implausible(f, edges.width, edges.height, tp);
    if (why.empty()) return f;
    why = "at the frame centre: " + why;
    return std::nullopt;
  }
  return s.edges_acquisition.acquire(gray, edges, est, params, limit, tp, budget, why);
}

namespace {

// Where the object of a start from the user's box lies: the box grown by
// ObjectModelParams::box_slack of its sides (empty: no box, or a box the track goes on from).
Rect users_box_bound(const TrackerState::Track& t, const ObjectModelParams& p) {
  if (!t.seed_box || t.last || !(p.box_slack >= 0)) return {};
  const Rect& b = *t.seed_box;
  const int dx = static_cast<int>(std::ceil(p.box_slack * b.width));
  const int dy = static_cast<int>(std::ceil(p.box_slack * b.height));
  return {b.x - dx, b.y - dy, b.width + 2 * dx, b.height + 2 * dy};
}

}  // namespace

AppearanceStart start_appearance_track(TrackerState& s, const ColorView& frame, EdgeSource& edges,
                                       const TrackerParams& tp, Mask& first, Mask& silhouette) {
  AppearanceStart out;
  const FinderParams fp = finder_params(tp, s.motion.spread());
  Point2i seed;
  if (!find_first_silhouette(s, frame, tp, fp, first, seed, out)) return out;
  const int scale = s.finder.scale();
  const bool ok =
      out.resumed
          ? s.object.resume(frame, edges, first, scale, seed, tp.object, silhouette)
          : s.object.start(frame, edges, first, scale, seed,
                           s.finder.apart_from_border() ? s.finder.border_colours() : kNoColours,
                           users_box_bound(s.track(), tp.object), tp.object, silhouette);
  if (!ok) {
    out.why = "nothing of the object's colours is left around it";
    return out;
  }
  if (!s.track().inner && !out.resumed) {
    out.why = veto_motion_start(s, frame, fp, silhouette);
    if (!out.why.empty()) {
      s.object.forget();
      return out;
    }
  }
  out.found = true;
  return out;
}

Stillness judge_stillness(TrackerState& s, const ColorView& frame, const Features& f,
                          const Mask& silhouette, const TrackerParams& tp) {
  // Almost none of its box changed since the last frame (compared on every frame, so that the
  // previous one is the last frame)...
  const FinderParams fp = finder_params(tp, s.motion.spread());
  bool still = s.motion.update(frame.luma, motion_params(tp, s.motion.spread()), s.moved);
  if (still) {
    std::size_t inside = 0;
    for (const Point2i& q : s.moved.points) inside += f.bbox.contains(q);
    still = static_cast<double>(inside) * s.moved.step * s.moved.step <
            fp.min_moving * f.bbox.width * f.bbox.height;
  }
  // ... and on this frame its silhouette is what the background holds there.
  still = still &&
          s.finder.foreground_share(frame, silhouette, s.object.scale(), fp) < fp.min_foreground;
  if (s.note_still(still) >= tp.still_frames) {
    s.forget_still();
    return Stillness::Drop;
  }
  return s.track().still > 0 ? Stillness::Holds : Stillness::Moves;
}

AfterRefusal after_refusal(const TrackerState& s, const TrackerParams& tp, bool forced) {
  AfterRefusal out;
  const TrackerState::Track& t = s.track();
  // An object found without the user's point whose estimates are refused on and off is a
  // fragment the estimates cannot hold (TrackerParams::unsteady).
  const int window = std::min(2 * tp.unsteady, 31);
  const bool unsteady =
      !forced && s.model() == ObjectModelKind::Appearance && !t.seeded && tp.unsteady > 0 &&
      t.refused_in_a_row == 1 &&
      static_cast<int>(std::bitset<32>(t.refusals & ((1u << window) - 1)).count()) >= tp.unsteady;
  if (unsteady) out.note = "; refused on and off: an unsteady fragment, not an object";
  out.drop = forced || unsteady || t.refused_in_a_row > tp.patience;
  if (out.drop) out.note += "; the track is dropped";
  return out;
}

void drop_refused_track(TrackerState& s) {
  // A track accepted on one frame only was never an object: its colours are not searched for.
  if (s.model() == ObjectModelKind::Appearance && s.track().accepted > 1)
    s.drop(TrackerState::Keep::Colours);
  else
    s.reset();
}

}  // namespace projtrack
