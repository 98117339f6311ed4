// Follows one object from frame to frame: finds it, keeps its inner point, notices when it is
// lost, finds it again, and turns its features into a 3D pointer (x, y, depth) with push clicks.
//
// One frame flows one way through the stages, each in its own file:
//   frame → edges (edge_source) and appearance (appearance_model)
//         → the object's silhouette (object_model, silhouette; object_finder when there is none)
//         → the estimator on it (estimator) → plausibility → pointer → TrackResult
// With ObjectModelKind::Edges the silhouette stage is skipped: the estimator runs on the edges
// themselves (edge_region), as in the paper, and motion_acquisition finds new objects.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "color_view.hpp"
#include "edge_detection.hpp"
#include "edge_source.hpp"
#include "estimator.hpp"
#include "mask.hpp"
#include "motion_acquisition.hpp"
#include "object_finder.hpp"
#include "object_model.hpp"
#include "pointer.hpp"
#include "silhouette_pieces.hpp"
#include "tracker_params.hpp"

namespace projtrack {

// What the tracker made of one frame: everything its users (the element's meta, message and
// overlay) report.
struct TrackResult {
  TrackStatus status = TrackStatus::NoInnerPoint;
  Features features;   // this frame's estimate; when Lost, the last accepted one (if any)
  std::string detail;  // why, when the status is Lost, Searching or without features
  // Where the tracker's inner point is after this frame, for the next one (none: not tracking).
  // While tracking, features.inner_point; while lost, where the track waits to go on.
  std::optional<Point2i> inner_point;
  bool acquired = false;  // tracking (re)started on this frame
  bool has_pose = false;  // tracking or lost (held) with an acquired object
  Pose pose;              // smoothed (when TrackerParams::smoothing)
  Pose raw_pose;
  bool push = false;  // a push completed on this frame
};

class Tracker {
 public:
  // Tracks from `p` on the next frame, whatever the acquisition mode: a new object.
  void seed(Point2i p);
  // Tracks the object in `box` (a user's rectangle around it) on the next frame: its centre is
  // the inner point; the appearance model takes the object's first silhouette within the box.
  void seed_box(const Rect& box);
  // Forgets the object; Auto and Center acquisition start over.
  void reset();
  // Where the inner point is now (also TrackResult::inner_point of the last frame).
  const std::optional<Point2i>& inner_point() const { return inner_; }

  // One frame taken at `t` seconds, with edges computed here with `edge_params`: only around the
  // object while tracking. A frame with chroma gives the appearance model its colours; a gray
  // one, luma alone.
  TrackResult track(const ColorView& frame, const EdgeParams& edge_params, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace = nullptr);
  TrackResult track(const ImageView& gray, const EdgeParams& edge_params, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace = nullptr);
  // The same with the edges of the whole frame given (an edge map made elsewhere).
  TrackResult track(const ColorView& frame, const ImageView& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace = nullptr);
  TrackResult track(const ImageView& gray, const ImageView& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace = nullptr);

 private:
  TrackResult track(const ColorView& frame, EdgeSource& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track_frame(const ColorView& frame, EdgeSource& edges, double t, Method m,
                          const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track_edges(const ColorView& frame, EdgeSource& edges, double t, Method m,
                          const Params& params, const TrackerParams& tp, Trace* trace);
  TrackResult track_appearance(const ColorView& frame, EdgeSource& edges, double t, Method m,
                               const Params& params, const TrackerParams& tp, Trace* trace);
  // The appearance model's first silhouette of an object: around the inner point, where its
  // colours are (an object lost before), or where the frame moves. False and `why` when none.
  bool find_object(const ColorView& frame, EdgeSource& edges, const TrackerParams& tp,
                   bool& resumed, std::string& why);
  // The estimator on the outline of silhouette_, from the inner point (or the silhouette's
  // deepest point when the inner point is not in it).
  Features estimate_on_silhouette(Method m, const Params& params, int width, int height,
                                  Trace* trace);
  Estimator& estimator(Method m);
  // Takes `f` as this frame's estimate; `resumed`: the same object found again after a loss.
  void accept(const Features& f, double t, int width, int height, const TrackerParams& tp,
              bool resumed, TrackResult& r);
  // Refuses this frame's estimate: reports the last accepted one; after `patience` refusals in
  // a row drops the track (the appearance model keeps the object's colours to find it again).
  void refuse(std::string why, const TrackerParams& tp, TrackResult& r);
  // Forgets where the object is; `keep_object`: its colours and its first area stay known.
  void drop(bool keep_object);
  // tp's motion and finder parameters with their grey-level thresholds scaled to the scene's
  // contrast (TrackerParams::full_contrast), as the last frame compared showed it.
  MotionDetector::Params motion_params(const TrackerParams& tp) const;
  FinderParams finder_params(const TrackerParams& tp) const;

  EdgeMap edge_map_;
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators_;  // made on first use
  std::optional<Point2i> inner_;
  std::optional<Rect> box_;  // the box a track was seeded with, until it starts
  std::optional<Features> last_good_;
  Point2d velocity_;  // of the centroid between the last two accepted frames, px per frame
  int refused_in_a_row_ = 0;
  std::uint32_t recent_refusals_ = 0;  // a bit per frame since the track started, newest lowest
  Pointer pointer_;
  ObjectModelKind model_ = ObjectModelKind::Appearance;

  // Edges model.
  MotionAcquisition acquisition_;

  // Appearance model.
  ObjectModel object_;
  ObjectFinder finder_;
  MotionDetector motion_;
  MotionDetector::Motion moved_;
  std::vector<Point2i> moved_before_;  // the changed samples of the frame before
  Mask silhouette_, first_;
  SilhouettePieces pieces_;
  Trace piece_trace_;
  bool split_ = false;  // estimate_on_silhouette() cuts the silhouette into pieces
  MaskOps ops_;
  std::vector<std::uint8_t> barrier_;
  double lost_area_ = 0;  // the object's area and centroid when it was lost
  Point2d lost_centroid_;
  int searched_ = 0;     // frames searched by colour since the loss
  bool seeded_ = false;  // the track started from the user's point or box
  int still_ = 0;        // frames in a row the object has not moved
};

}  // namespace projtrack
