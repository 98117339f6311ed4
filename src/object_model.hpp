// The object as the tracker knows it between frames: its silhouette and its colours against its
// surroundings'. Finds the object's silhouette on each new frame near the last one, and learns.
// It works at a scale picked from the object's size (see WorkFrame): its masks are in work
// coordinates at scale().
#pragma once

#include <cstdint>
#include <vector>

#include "appearance_model.hpp"
#include "color_view.hpp"
#include "edge_source.hpp"
#include "mask.hpp"
#include "silhouette.hpp"
#include "work_frame.hpp"

namespace projtrack {

struct ObjectModelParams {
  // The working scale makes the object about this many work pixels (whole pixels when smaller).
  double work_pixels = 6000;
  // The surroundings the colours are learned against: a ring this share of √area wide around
  // the silhouette (at least 8 px). Wide enough to take in the hand that holds the object.
  double ring = 0.5;
  // At the start, only the colours of the disc around the seed are the object's (its radius the
  // seed's depth in the first silhouette, at least this share of √area): a first silhouette may
  // take in part of the hand, the disc does not.
  double core = 0.2;
  int start_rounds = 3;  // rounds of segmenting and learning on the first frame
  // On the first frame the silhouette may reach this share of √area beyond the first one: across
  // a finger to the object's part on its other side.
  double start_reach = 0.25;
  // How fast the colours follow the object's: the share of one frame in the model. The model
  // learns every `learn_every` frames (at the rate of as many frames), which costs less.
  double learning_rate = 0.05;
  int learn_every = 3;
  // The silhouette may move this share of √area (at least 2 work px) beyond the last one moved
  // by the object's motion; the region searched is its box grown by `margin` of its larger side.
  double reach = 0.08;
  double margin = 0.15;
  // Before segmenting, the prior is moved to the object-like pixels within this share of √area
  // of it (mean shift): an object faster than its predicted motion.
  double window = 0.25;
  // Edge-bounded regions under this share of the expected area are taken or left whole.
  double small_region = 1.25;
  // A first silhouette that reaches the frame's border has taken in the arm that holds the
  // object (a held object is in the picture): it is cut where it is thinner than twice this share
  // of √area (an opening), and the pieces that then reach the border are dropped, unless the seed
  // is in one.
  double arm_cut = 0.1;
};

class ObjectModel {
 public:
  // Forgets the object and its colours.
  void reset();
  // Forgets where the object is, keeps its colours (to find it again).
  void lose() { silhouette_.reset({}); }
  bool tracking() const { return !silhouette_.empty(); }
  bool knows_colours() const { return !appearance_.empty(); }
  int scale() const { return scale_; }
  // The last silhouette, in work coordinates at scale().
  const Mask& silhouette() const { return silhouette_; }
  const AppearanceModel& appearance() const { return appearance_; }

  // Starts from a first silhouette `first` (work coordinates at `first_scale`) found around
  // `seed` (a frame pixel): learns the colours of its core against the colours of the frame's
  // border (`background`, counts per colour bin), then segments and learns again on this frame
  // against a ring around it. Holds the result as the silhouette and puts it in `out`; false when
  // nothing is left of the object.
  bool start(const ColorView& frame, EdgeSource& edges, const Mask& first, int first_scale,
             Point2i seed, const std::vector<std::uint32_t>& background, const ObjectModelParams& p,
             Mask& out);
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
  // The arm cut (ObjectModelParams::arm_cut) of `s`, when it reaches `frame` (work coordinates).
  void cut_arm(Mask& s, const Rect& frame, Point2i seed, const ObjectModelParams& p);
  // Moves `prior` onto the object-like pixels within `window` work px of its box.
  void recentre(Mask& prior, int window);
  // Learns the colours of `object` against a ring around the convex hull of `silhouette` (on this
  // frame's work frame).
  void learn(const Mask& object, const Mask& silhouette, double ring, double rate);
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
  RegionLabels pieces_;            // cut_arm(): the pieces left by the opening
  std::vector<std::uint8_t> arm_;  // per piece: it reaches the frame's border
  int scale_ = 1;
  int unlearned_ = 0;  // accepted frames since the model last learned
  Mask silhouette_, prior_, core_, grown_, ring_, hull_;
  std::vector<std::uint8_t> likelihood_, edge_buffer_;
};

}  // namespace projtrack
