// Follows one object from frame to frame: finds it, keeps its inner point, notices when it is
// lost, finds it again, and turns its features into a 3D pointer (x, y, depth) with gestures.
//
// One frame flows one way through the stages, a folder of src/ each (docs/architecture.md):
//   frame → what the frame gives every object model (models/frame_evidence: its edges, edges/,
//           and the frame at a working scale, segmentation/work_images, each built on demand;
//           the frame's work budget)
//         → the object model (models/<name>/, ObjectModelKind): a start, or the followed object
//           (ObjectModelKind::Flow: its silhouette carried along the motion, motion/, and cut by
//           colour and motion, segmentation/; acquisition/moving_object when there is none)
//         → the estimator on its silhouette (estimators/) → the tracker's verdict (tracker/)
//         → pointer/ → TrackResult
// With ObjectModelKind::Edges there is no silhouette: the estimator runs on the edges themselves
// (models/edges/edge_region), as in the paper, and acquisition/motion_acquisition finds new
// objects.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "color_view.hpp"
#include "edge_detection.hpp"
#include "features.hpp"
#include "geometry.hpp"
#include "gesture.hpp"
#include "image_view.hpp"
#include "method.hpp"
#include "params.hpp"
#include "pose.hpp"
#include "settings.hpp"
#include "silhouette_mask.hpp"
#include "trace.hpp"
#include "tracker_params.hpp"

namespace projtrack {

// What the tracker made of one frame: everything its users (the element's meta, message and
// overlay) report.
struct TrackResult {
  // The object's id in a MultiTracker (from 1, never reused within a stream); 0 from a Tracker.
  int id = 0;
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
  Gesture gesture = Gesture::None;  // a gesture completed on this frame (a release: also when
                                    // the track ended while pressed)
  // The work this frame's estimates did (work units, work_budget.hpp), against its budget
  // (frame_work_limit(): WorkBudget::kUnlimited when TrackerParams::max_work is 0).
  std::uint64_t work = 0;
  std::uint64_t work_limit = 0;
};

class Tracker {
 public:
  Tracker();
  ~Tracker();
  Tracker(Tracker&&) noexcept;  // a moved-from Tracker can only be assigned to or destroyed
  Tracker& operator=(Tracker&&) noexcept;

  // Tracks from `p` on the next frame, whatever the acquisition mode: a new object.
  void seed(Point2i p);
  // Tracks the object in `box` (a user's rectangle around it) on the next frame: its centre is
  // the inner point; the flow model cuts the object's first silhouette out of the box.
  void seed_box(const Rect& box);
  // Tracks the object `mask` covers (non-zero on it, the frame's size: OpenCV's convention) on
  // the next frame: the flow model starts from exactly that silhouette; the edges model from its
  // deepest point as the inner point. False, changing nothing, when the mask holds no pixel or
  // has no usable shape (no data, stride < width).
  bool seed_mask(const ImageView& mask);
  // Forgets the object; Auto and Center acquisition start over.
  void reset();
  // Where the inner point is now (also TrackResult::inner_point of the last frame).
  const std::optional<Point2i>& inner_point() const;
  // A flag another thread may set to stop the frame being tracked at its next checkpoint (a ray,
  // a fill's run, a seed): that frame ends with TrackStatus::Interrupted and the track is kept as
  // it was; so does every frame while the flag is set. Null: none. The flag must outlive the
  // Tracker (or be replaced).
  void set_stop_flag(const std::atomic<bool>* stop);
  // The object's silhouette as the tracker holds it after the last frame (the object model's:
  // that frame's when it was accepted, else the last accepted one carried along the picture's
  // motion to that frame),
  // drawn into the caller's width × height mask of that frame (rows `stride` bytes apart): 255 on
  // the object, 0 elsewhere. False, with the mask all 0, when the tracker holds none (the edges
  // model, no object, a dropped track) or the mask's shape is unusable (no data, stride < width).
  bool silhouette(std::uint8_t* mask, int width, int height, std::ptrdiff_t stride) const;
  // The same silhouette (the flow model's; empty with the edges model, or without a track). A
  // view into the tracker.
  SilhouetteMask silhouette() const;
  // The frames change size, from width × height to new_width × new_height (a new resolution):
  // the inner point, the user's box and the last estimate are scaled (depth, the object's share
  // of the frame, needs no scaling); the flow model's silhouette follows and its colours stay,
  // and on the next frame the object is looked for by its colours near where it was (the stream
  // may have been cut there) before it is followed on. The track goes on: no new acquisition,
  // depth goes on; the centroid's step across the change is no velocity, and the next estimate is
  // judged against the last at TrackerParams::leak_factor².
  void rescale(int width, int height, int new_width, int new_height);
  // The frames' colours are read another way (another pixel format, same size): on the next
  // frame the flow model holds its silhouette where it was and learns the object's colours and
  // its surroundings' anew there (those learned on the old format would not find it); the track
  // goes on, as after rescale().
  void relearn();

  // One frame taken at `t` seconds with the settings bundle `s` (settings.hpp): as the overloads
  // below, with s's method, parameters, edges and tracker parameters.
  TrackResult track(const ColorView& frame, double t, const Settings& s, Trace* trace = nullptr);
  TrackResult track(const ImageView& gray, double t, const Settings& s, Trace* trace = nullptr);
  // One frame taken at `t` seconds, with edges computed here with `edge_params`: only around the
  // object while tracking. A frame with chroma gives the flow model its colours; a gray one,
  // luma alone.
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
  // The stages and what they keep between frames (src/tracker/tracker_impl.hpp): an application
  // needs none of their headers.
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace projtrack
