// Finds an object's first silhouette, before any model of it exists: around a point the user
// gave, where the frame moves, or, for an object seen before, where its colours are.
#pragma once

#include <string>
#include <vector>

#include "acquisition/motion_detector.hpp"
#include "acquisition/seed_region.hpp"
#include "appearance/appearance_model.hpp"
#include "core/mask.hpp"
#include "core/region_labels.hpp"
#include "core/work_frame.hpp"
#include "projtrack/color_view.hpp"
#include "projtrack/finder_params.hpp"

namespace projtrack {

// What from_motion() says when no region of its own colours moves at all (rather than one that
// moves but must wait).
inline constexpr const char* kNoMovingRegion =
    "no moving region of its own colours, wholly in view";

// Every silhouette it finds is in work coordinates at scale() (see WorkFrame).
class ObjectFinder {
 public:
  int scale() const { return work_.scale(); }
  // The share of `s` (work coordinates at `scale`) that differs from the scene's background, as
  // the last search from motion or by colour learned it; 1 while it is not yet known.
  double foreground_share(const Mask& s, int scale, const FinderParams& p) const;
  // The same on `frame`, a frame it has not searched (a tracked one): read into a work frame of
  // its own, so that the search's state is left as it was.
  double foreground_share(const ColorView& frame, const Mask& s, int scale,
                          const FinderParams& p) const;
  // The colours of the frame's border strip on the last search from a seed or by motion:
  // counts per AppearanceModel colour bin, at scale().
  const std::vector<std::uint32_t>& border_colours() const { return border_counts_; }
  // Whether the last silhouette found is of colours the frame's border does not show (so the
  // object's colours can be learned against the border's); false when it was grown from the
  // user's point by its own colour, which the border shows too.
  bool apart_from_border() const { return apart_from_border_; }
  // The object around `seed`: the 4-connected region of colours not seen on the frame's border
  // (the wall, the table and the arm that holds an object reach the border), its holes filled.
  // When the border shows the seed's own colour too, the region grown from the seed by its own
  // colour (SeedRegion); failing that, the nearest region of colours the border does not show.
  // False (and `why`) when there is none within reach of the seed.
  bool from_seed(const ColorView& frame, Point2i seed, const FinderParams& p, Mask& out,
                 std::string& why);
  // The object in `box` (frame pixels): the region around the box's centre as from_seed finds it,
  // kept within the box; the ellipse inscribed in the box when no such region is there.
  bool from_box(const ColorView& frame, const Rect& box, const FinderParams& p, Mask& out,
                std::string& why);
  // The moving object: of the regions of colours not seen on the border, the one with the most
  // moving pixels for its size that does not touch the border (the arm that waves an object
  // does) and is not static. It must have moved in `before` too (the last frame that showed
  // motion), by half as much: a passer-by that crossed a static region for one frame does not
  // make that region an object. `seed` gets its deepest point.
  bool from_motion(const ColorView& frame, const MotionDetector::Motion& motion,
                   const MotionDetector::Motion& before, const FinderParams& p, Mask& out,
                   Point2i& seed, std::string& why);
  // The moving object when no region of its own colours is (its colours are the border's too):
  // the largest blob of changed samples wholly in view that moved on the last frame too, and
  // in it, as in a user's box, the region of the object's colours. It reads the work frame
  // from_motion() built: call it after from_motion() on the same frame.
  bool from_moving_blob(const ColorView& frame, const MotionDetector::Motion& motion,
                        const MotionDetector::Motion& before, const FinderParams& p, Mask& out,
                        Point2i& seed, std::string& why);
  // An object seen before: of the regions whose colours the model finds object-like, the one
  // closest in size to `area` (frame px², within `factor`) and nearest `near`, that moves.
  bool from_model(const ColorView& frame, const AppearanceModel& model,
                  const MotionDetector::Motion& motion, double area, double factor, Point2d near,
                  const FinderParams& p, Mask& out, Point2i& seed, std::string& why);

 private:
  // The whole frame at the finder's scale, into `work`.
  static void load(const ColorView& frame, const FinderParams& p, WorkFrame& work);
  // foreground_share() of `s` against the background, on `work`.
  double foreground_share(const WorkFrame& work, const Mask& s, int scale,
                          const FinderParams& p) const;
  // The pixels whose colours are not seen on the border, into candidates_.
  void foreground(const FinderParams& p);
  // Samples of `motion` per labelled region: in it, and within one work pixel of it.
  struct MotionCounts {
    std::vector<std::int64_t> inside, near;
    double per_sample = 0;  // the work pixels a sample stands for
  };
  // Counted only within `area` (work pixels): the counts are those of every region whose box,
  // grown by one pixel, lies in it. The samples are first counted per work pixel, so that the
  // regions are looked up once per work pixel that moved, not once per sample (a frame of fresh
  // noise moves almost every sample).
  void count_motion(const MotionDetector::Motion& motion, const Rect& area, MotionCounts& out);
  // Whether region `l` (of `stats_`, see best_region) moved by FinderParams::min_moving or
  // min_moving_outline, times `share`.
  bool moves(int l, const MotionCounts& m, const FinderParams& p, double share = 1) const;
  // Updates the background with the loaded frame; then, per labelled region, its pixels that
  // differ from the background (all of them while the background is not yet known).
  void count_foreground(const FinderParams& p);
  // The size, outline and box of every labelled region of candidates_, into stats_.
  void measure_regions();
  // The union of the boxes, grown by one pixel, of the regions `keep` accepts: where motion is
  // worth counting (a region that fails the other tests first needs none).
  template <class Keep>
  Rect area_of(Keep&& keep) const;
  // Picks the best measured region by `score` (higher is better, < 0 refused); 0 for none.
  template <class Score>
  int best_region(Score&& score) const;
  void copy_region(int label, Mask& out);
  // The region of colours the border does not show at `seed` or nearest it (within a twentieth
  // of the frame), its holes filled; false when there is none. Needs foreground().
  bool nearest_apart_region(Point2i seed, const FinderParams& p, Mask& out);
  // Whether `p` lies within the convex hull of `region` (enclosure_ its scratch).
  bool around_point(const Mask& region, Point2i p);
  // from_seed(), and from_box() with `box` (work coordinates): the candidates kept within it.
  // On the work frame load() made of this frame.
  bool around_seed(Point2i seed_pixel, const FinderParams& p, const Rect* box, Mask& out,
                   std::string& why);
  static void clip_to(const Rect& box, Mask& m);
  // Whether `m` (work coordinates) moves as moves() asks of a labelled region: by its area, or
  // along its outline.
  bool mask_moves(const Mask& m, const MotionDetector::Motion& motion, const FinderParams& p);
  // Whether everything around `m` is of colours the border does not show: `m` is a part (a
  // print) of a larger object, not one itself. Needs foreground().
  bool within_apart_region(const Mask& m);
  // The smallest labelled region of at least `least` pixels, other than `inner`, that encloses
  // work pixel `p` (it lies in the region's holes); 0 for none.
  int enclosing_region(Point2i p, int inner, double least);

  struct RegionStats {
    std::int64_t size = 0;
    std::int64_t outline = 0;  // pixels with a 4-neighbour outside the region
    Rect box;
  };
  std::vector<RegionStats> stats_;
  std::vector<BoundsAccumulator> bounds_;
  std::vector<std::uint32_t> border_counts_;
  std::vector<std::uint8_t> background_;  // per colour bin
  std::vector<std::uint8_t> like_;
  Mask candidates_, opened_, enclosure_, by_colour_, blobs_;
  RegionLabels regions_;
  SeedRegion seed_region_;
  bool apart_from_border_ = true;
  MotionCounts moving_, moving_before_;
  std::vector<std::int32_t> samples_;      // motion samples per work pixel (count_motion)
  std::vector<std::int32_t> work_column_;  // a frame column's work column (count_motion)
  std::vector<std::int64_t> foreground_;
  std::vector<float> scene_;  // the background: running mean luma, at the finder's scale
  Rect scene_rect_;
  int scene_seen_ = 0;
  MaskOps ops_;
  WorkFrame work_;             // the frame searched last
  mutable WorkFrame checked_;  // a tracked frame foreground_share() reads
};

}  // namespace projtrack
