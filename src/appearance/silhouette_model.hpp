// The appearance object model (ObjectModelKind::Appearance): the object as the tracker knows it
// between frames, its silhouette and its colours against its surroundings'. Finds the object's
// silhouette on each new frame near the last one, and learns.
// It works at a scale picked from the object's size (see WorkFrame): its masks are in work
// coordinates at scale().
#pragma once

#include <cstdint>
#include <vector>

#include "appearance/appearance_model.hpp"
#include "appearance/silhouette.hpp"
#include "core/mask.hpp"
#include "core/work_frame.hpp"
#include "edges/edge_source.hpp"
#include "projtrack/color_view.hpp"
#include "projtrack/object_model_params.hpp"

namespace projtrack {

class SilhouetteModel {
 public:
  // Forgets the object and its colours.
  void forget();
  // Forgets where the object is, keeps its colours (to find it again).
  void forget_position() { silhouette_.reset({}); }
  // The frame was resized by sx × sy: the silhouette follows at a work scale as much larger, its
  // colours stay (a resize changes no colour).
  void rescale(double sx, double sy);
  bool tracking() const { return !silhouette_.empty(); }
  bool knows_colours() const { return !appearance_.empty(); }
  int scale() const { return scale_; }
  // The last silhouette, in work coordinates at scale().
  const Mask& silhouette() const { return silhouette_; }
  const AppearanceModel& appearance() const { return appearance_; }

  // Starts from a first silhouette `first` (work coordinates at `first_scale`) found around
  // `seed` (a frame pixel): learns the colours of its core against the colours of the frame's
  // border (`background`, counts per colour bin; empty: against a ring around `first`), then
  // segments and learns again on this frame against a ring around it, within `bound` (frame
  // pixels; empty: anywhere). Holds the result as the silhouette and puts it in `out`; false when
  // nothing is left of the object.
  bool start(const ColorView& frame, EdgeSource& edges, const Mask& first, int first_scale,
             Point2i seed, const std::vector<std::uint32_t>& background, const Rect& bound,
             const ObjectModelParams& p, Mask& out);
  // Resumes an object found again by its colours around `first`: segments with the colours it
  // knows (learning nothing until accept()) and holds the result as the silhouette.
  bool resume(const ColorView& frame, EdgeSource& edges, const Mask& first, int first_scale,
              Point2i seed, const ObjectModelParams& p, Mask& out);
  // This frame's silhouette near the last one moved by `motion` (frame px), holding `hint` (a
  // frame pixel: the inner point) when it can. Learns nothing and keeps the last silhouette.
  bool find(const ColorView& frame, EdgeSource& edges, Point2d motion, Point2i hint,
            const ObjectModelParams& p, Mask& out);
  // Takes `s` (this frame's silhouette from find()) as the object's and learns its colours at
  // `p.learning_rate`.
  void accept(const Mask& s, const ObjectModelParams& p);

 private:
  // The work frame of `box` (work coordinates) grown by `margin`, and by the ring's width when
  // the model learns on this frame.
  void load(const ColorView& frame, const Rect& box, int margin, double area, bool learning,
            const ObjectModelParams& p);
  // The likelihood of the loaded work frame, into likelihood_ (load() does it).
  void score();
  // The arm cut (ObjectModelParams::arm_cut) of `s`, when it reaches `frame` (work coordinates):
  // the pieces that reach the border, hold not the seed and lie mostly outside `before` (the
  // silhouette it grew from) go.
  void cut_arm(Mask& s, const Mask& before, const Rect& frame, Point2i seed,
               const ObjectModelParams& p);
  // Moves `prior` onto the object-like pixels within `window` work px of its box.
  void recentre(Mask& prior, int window);
  // Learns the colours of `object` against a ring around the convex hull of `silhouette` (on this
  // frame's work frame); `past_outline`: the ring leaves out the band of mixed colours along it.
  void learn(const Mask& object, const Mask& silhouette, double ring, double rate,
             bool past_outline);
  // `first`: a first silhouette, which keeps every object-like piece within reach of the prior.
  bool segment(EdgeSource& edges, const Mask& prior, double area, Point2i hint, int reach,
               const ObjectModelParams& p, Mask& out, bool first = false);
  // Adds to `s` the pixels inside its convex hull whose colours are not the surroundings'.
  void take_unknown_inside(Point2i seed, Mask& s);
  Point2i to_work(Point2i frame_pixel) const;

  AppearanceModel appearance_;
  SilhouetteSegmenter segmenter_;
  WorkFrame work_;
  EdgeMap edge_map_;
  MaskOps ops_;
  RegionLabels pieces_;                     // cut_arm(): the pieces left by the opening
  std::vector<std::uint8_t> arm_;           // per piece: it is the arm (cut_arm)
  std::vector<std::int64_t> piece_before_;  // per piece: its pixels in before
  int scale_ = 1;
  int unlearned_ = 0;  // accepted frames since the model last learned
  // What of a first silhouette `s` the start learns the colours from (in core_ or `s` itself):
  // where it is thicker than an arm (an opening by ObjectModelParams::arm_cut of √area), less its
  // outline pixel. A band along the hand that holds the object (its shadowed underside) that the
  // start's segmentation let in is then not learned as the object's, and does not grow round by
  // round. (While tracking, the whole silhouette is learned: an object's own thin parts, a hand's
  // fingers, would otherwise fade from the model.)
  const Mask& learning_core(const Mask& s, const ObjectModelParams& p);
  Mask silhouette_, prior_, core_, grown_, ring_, hull_;
  std::vector<std::uint8_t> likelihood_, edge_buffer_;
};

}  // namespace projtrack
