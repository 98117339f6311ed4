// How the appearance model starts a track: the user's point or box, the frame centre, an object
// lost before found by its colours, or what moves; the vetoes of a start nobody asked for; and
// the stillness check of a track found that way.
#include <algorithm>
#include <cmath>
#include <utility>

#include "acquisition/motion_gate.hpp"
#include "models/appearance/appearance_memory.hpp"

namespace projtrack {

namespace {

// How much dimmer than TrackerParams::full_contrast the scene is: 1 at full contrast, at least ⅓.
double contrast(int spread, const TrackerParams& tp) {
  if (spread <= 0 || !(tp.full_contrast > 0)) return 1.0;
  return std::clamp(spread / tp.full_contrast, 1.0 / 3, 1.0);
}

// The share of the frame that must change before acquisition looks: TrackerParams::min_motion,
// or for an object lost before whose colours are known, a tenth of its own area if that is less
// (a small ball rolling moves far less of the frame than a held cup).
double least_motion(const AppearanceMemory& m, const Track& track, const TrackerParams& tp,
                    const ImageView& frame) {
  const double pixels = static_cast<double>(frame.width) * frame.height;
  if (!m.object.knows_colours() || !(track.lost_area > 0) || pixels <= 0) return tp.min_motion;
  return std::min(tp.min_motion, 0.1 * track.lost_area / pixels);
}

// Auto acquisition: an object lost before, by its colours (forgotten after
// TrackerParams::forget_after frames of search); else whatever moves. Needs the frame to move.
bool find_by_motion_or_colours(AppearanceMemory& m, const ColorView& frame, const Track& track,
                               const TrackerParams& tp, const FinderParams& fp, Mask& first,
                               Point2i& seed, AppearanceStart& out) {
  const double gate = least_motion(m, track, tp, frame.luma);
  // The last frame that showed motion, for the finder's check that what moves now moved then
  // too (a frame repeated by the camera or the encoder shows none, and does not count).
  if (m.moved.fraction >= gate) std::swap(m.moved_before, m.moved);
  out.why =
      wait_for_motion(m.motion, frame.luma, motion_params(tp, m.motion.spread()), gate, m.moved);
  if (!out.why.empty()) return false;
  // A new object is what moves apart from the rest: changes spread evenly over the whole frame
  // (fresh noise, a flash) show none, and looking would read the whole frame for nothing. An
  // object whose colours are known is looked for still (sensor noise moves every part of the
  // frame, and the object with it).
  if (!m.object.knows_colours() && changed_evenly(m.moved, frame.luma.width, frame.luma.height)) {
    out.why = "the whole picture changed evenly: nothing moves apart from it";
    return false;
  }
  if (m.object.knows_colours() && m.searched >= tp.forget_after) {
    m.object.forget();  // not seen for long: look for any object
    m.searched = 0;
  }
  ++m.searched;
  if (m.object.knows_colours()) {
    out.resumed =
        m.finder.from_model(frame, m.object.appearance(), m.moved, track.lost_area, tp.leak_factor,
                            track.lost_centroid, fp, first, seed, out.why);
    return out.resumed;
  }
  if (m.finder.from_motion(frame, m.moved, m.moved_before, fp, first, seed, out.why)) return true;
  // No region of colours the border does not show moves: the moving object's colours are the
  // border's too (a dark puck on a table with dark edges); look where the frame moves.
  if (out.why != kNoMovingRegion) return false;
  return m.finder.from_moving_blob(frame, m.moved, m.moved_before, fp, first, seed, out.why);
}

// The finder's first silhouette, into `first`, and the point it grew from, into `seed`.
bool find_first_silhouette(AppearanceMemory& m, const ColorView& frame, const StartRequest& request,
                           const Track& track, const TrackerParams& tp, const FinderParams& fp,
                           Mask& first, Point2i& seed, AppearanceStart& out) {
  const int w = frame.luma.width, h = frame.luma.height;
  seed = {w / 2, h / 2};
  if (request.from != StartRequest::From::Nothing) {
    seed = request.point;
    if (!Rect{0, 0, w, h}.contains(seed)) {
      out.why = "the inner point lies outside the frame";
      return false;
    }
    return request.from == StartRequest::From::Point
               ? m.finder.from_seed(frame, seed, fp, first, out.why)
               : m.finder.from_box(frame, request.box, fp, first, out.why);
  }
  if (tp.acquisition == Acquisition::Center) {
    const bool found = m.finder.from_seed(frame, seed, fp, first, out.why);
    if (!found) out.why = "at the frame centre: " + out.why;
    return found;
  }
  return find_by_motion_or_colours(m, frame, track, tp, fp, first, seed, out);
}

// Why an object found by motion alone is no start, if it is not one: a silhouette that grew from
// it to the frame's border has run into the arm that holds it (or the table); one that is the
// scene's background is a static region that a passer-by's colours joined.
std::string veto_motion_start(AppearanceMemory& m, const ColorView& frame, const FinderParams& fp,
                              const Mask& silhouette) {
  const int w = frame.luma.width, h = frame.luma.height;
  const Rect b = to_frame(moments(silhouette).bbox, m.object.scale(), w, h);
  if (b.x <= 0 || b.y <= 0 || b.right() >= w || b.bottom() >= h)
    return "what moved there runs into the frame's border (an arm, not an object): left alone";
  if (m.finder.foreground_share(silhouette, m.object.scale(), fp) < fp.min_foreground)
    return "what moved there is the background (a static region): left alone";
  return {};
}

// Where the object of a start from the user's box lies: the box grown by
// ObjectModelParams::box_slack of its sides (empty: no box, or a box the track goes on from).
Rect users_box_bound(const StartRequest& request, const Track& track, const ObjectModelParams& p) {
  if (request.from == StartRequest::From::Nothing || request.from == StartRequest::From::Point ||
      track.last || !(p.box_slack >= 0))
    return {};
  const Rect& b = request.box;
  const int dx = static_cast<int>(std::ceil(p.box_slack * b.width));
  const int dy = static_cast<int>(std::ceil(p.box_slack * b.height));
  return {b.x - dx, b.y - dy, b.width + 2 * dx, b.height + 2 * dy};
}

const std::vector<std::uint32_t> kNoColours;

}  // namespace

void AppearanceMemory::forget_motion() {
  motion.reset();
  moved = {};
  moved_before = {};
}

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

AppearanceStart start_appearance_track(AppearanceMemory& m, const ColorView& frame,
                                       EdgeSource& edges, const StartRequest& request,
                                       const Track& track, const TrackerParams& tp, Mask& first,
                                       Mask& silhouette) {
  AppearanceStart out;
  const FinderParams fp = finder_params(tp, m.motion.spread());
  Point2i seed;
  if (!find_first_silhouette(m, frame, request, track, tp, fp, first, seed, out)) return out;
  const int scale = m.finder.scale();
  const bool ok =
      out.resumed
          ? m.object.resume(frame, edges, first, scale, seed, tp.object, silhouette)
          : m.object.start(frame, edges, first, scale, seed,
                           m.finder.apart_from_border() ? m.finder.border_colours() : kNoColours,
                           users_box_bound(request, track, tp.object), tp.object, silhouette);
  if (!ok) {
    out.why = "nothing of the object's colours is left around it";
    return out;
  }
  if (request.from == StartRequest::From::Nothing && !out.resumed) {
    out.why = veto_motion_start(m, frame, fp, silhouette);
    if (!out.why.empty()) {
      m.object.forget();
      return out;
    }
  }
  out.found = true;
  return out;
}

Stillness judge_stillness(AppearanceMemory& m, const ColorView& frame, const Features& f,
                          const Mask& silhouette, const TrackerParams& tp) {
  // Almost none of its box changed since the last frame (compared on every frame, so that the
  // previous one is the last frame)...
  const FinderParams fp = finder_params(tp, m.motion.spread());
  bool still = m.motion.update(frame.luma, motion_params(tp, m.motion.spread()), m.moved);
  if (still) {
    std::size_t inside = 0;
    for (const Point2i& q : m.moved.points) inside += f.bbox.contains(q);
    still = static_cast<double>(inside) * m.moved.step * m.moved.step <
            fp.min_moving * f.bbox.width * f.bbox.height;
  }
  // ... and on this frame its silhouette is what the background holds there.
  still = still &&
          m.finder.foreground_share(frame, silhouette, m.object.scale(), fp) < fp.min_foreground;
  m.still = still ? m.still + 1 : 0;
  if (m.still >= tp.still_frames) {
    m.still = 0;
    return Stillness::Drop;
  }
  return m.still > 0 ? Stillness::Holds : Stillness::Moves;
}

}  // namespace projtrack
