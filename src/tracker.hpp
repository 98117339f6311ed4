// Follows one object from frame to frame: finds it, keeps its inner point, notices when it is
// lost, finds it again, and turns its features into a 3D pointer (x, y, depth) with push clicks.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "edge_detection.hpp"
#include "estimator.hpp"
#include "motion_detector.hpp"
#include "one_euro_filter.hpp"
#include "push_detector.hpp"

namespace projtrack {

// How tracking starts when there is no object.
enum class Acquisition {
  Manual,  // wait for an inner point (a property or a click)
  Center,  // try the frame centre
  Auto,    // the most relevant object: see AutoAcquisition
};

// How Acquisition::Auto picks the object (compared in docs/benchmarks.md).
enum class AutoAcquisition {
  MotionCentroid,       // the original system's: the centroid of the changed pixels
  CompactMovingRegion,  // the changed pixels as candidate seeds; the most compact moving fill
};

struct TrackerParams {
  Acquisition acquisition = Acquisition::Auto;
  AutoAcquisition strategy = AutoAcquisition::CompactMovingRegion;
  MotionDetector::Params motion{25, 4};
  double min_motion = 0.002;  // share of the frame that must change before Auto looks
  int candidates = 12;        // seeds CompactMovingRegion tries per frame
  int min_acquired_side = 8;  // px: a region thinner than this is not acquired

  // An estimate is refused (status Lost) when its area leaves [1/leak_factor, leak_factor] × the
  // last accepted one (a leak, or the inner point fell into a small region), exceeds
  // max_area × the frame, falls under min_area × the frame, or has no features at all.
  double leak_factor = 2.0;
  double max_area = 0.5;
  double min_area = 0.0005;
  int patience = 5;  // refused frames in a row tolerated; the next one drops the track

  // While tracking, edges are needed only around the object: the last box, and that box moved by
  // the object's last motion, grown by this share of its larger side (at least 16 px). An estimate
  // that reaches the region's edge is redone on a region grown by four times the margin, then on
  // the whole frame. Negative: always the whole frame.
  double edge_margin = 0.1;

  bool smoothing = true;  // One Euro filter on x, y and depth
  OneEuroFilter::Params filter;
  PushDetector::Params push;
};

// The 3D pointer: x, y in [-1, 1] from the centroid (0 at the frame centre, +1 at the right and
// bottom edges); depth 1 at acquisition, then sqrt(area / area at acquisition): it rises as the
// object nears the camera.
struct Pose {
  double x = 0, y = 0, depth = 1;
};

struct TrackResult {
  Status status = Status::NoInnerPoint;
  Features features;      // this frame's estimate; when Lost, the last accepted one (if any)
  std::string detail;     // why, when the status is Lost, Searching or without features
  bool acquired = false;  // tracking (re)started on this frame
  bool has_pose = false;  // tracking or lost (held) with an acquired object
  Pose pose;              // smoothed (when TrackerParams::smoothing)
  Pose raw_pose;
  bool push = false;  // a push completed on this frame
};

// Where the tracker gets its edges: a given edge map of the whole frame, or edges computed on
// demand for the region it needs (EdgeMap::detect with a region).
class EdgeSource {
 public:
  explicit EdgeSource(const ImageView& frame_edges) : given_(frame_edges) {}
  EdgeSource(EdgeMap& map, const ImageView& gray, const EdgeParams& params)
      : map_(&map), gray_(gray), params_(params) {}
  const ImageView& frame() const { return map_ ? gray_ : given_; }
  // The edges of `region` (clipped to the frame).
  ImageView region(const Rect& r);
  // How far from a region's inner border its edges may differ from the whole frame's: the blur
  // passes after the first, and Canny's own 3×3 neighbourhood (0 for given edges).
  int border_guard() const { return map_ ? std::clamp(params_.blur, 0, kMaxBlurPasses) + 3 : 0; }

 private:
  ImageView given_;
  EdgeMap* map_ = nullptr;
  ImageView gray_;
  EdgeParams params_;
};

class Tracker {
 public:
  // Tracks from `p` on the next frame, whatever the acquisition mode.
  void seed(Point2i p);
  // Forgets the object; Auto and Center acquisition start over.
  void reset();
  const std::optional<Point2i>& inner_point() const { return inner_; }

  // One frame taken at `t` seconds: `gray`, and edges computed here with `edge_params` — only
  // around the object while tracking (TrackerParams::edge_margin).
  TrackResult track(const ImageView& gray, const EdgeParams& edge_params, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace = nullptr);
  // The same with the edges of the whole frame given (an edge map made elsewhere).
  TrackResult track(const ImageView& gray, const ImageView& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace = nullptr);

 private:
  TrackResult track(const ImageView& gray, EdgeSource& edges, double t, Method m,
                    const Params& params, const TrackerParams& tp, Trace* trace);
  Estimator& estimator(Method m);
  // The estimate from the inner point, on the edges around the last box when there is one.
  Features estimate_around(EdgeSource& edges, Method m, const Params& params,
                           const TrackerParams& tp, Trace* trace);
  // Empty when `f` is acceptable as a new track's first estimate in `frame`; otherwise why not.
  std::string implausible(const Features& f, const ImageView& frame, const TrackerParams& tp) const;
  // Empty when `f` continues the track; otherwise why it is refused.
  std::string refused(const Features& f, const ImageView& frame, const TrackerParams& tp) const;
  // The area above which an estimate is refused (the fills stop there), px².
  double area_limit(const ImageView& frame, const Params& params, const TrackerParams& tp) const;
  std::optional<Features> acquire(const ImageView& gray, const ImageView& edges, Method m,
                                  const Params& params, const TrackerParams& tp, std::string& why);
  void accept(const Features& f, double t, const ImageView& frame, const TrackerParams& tp,
              TrackResult& r);

  EdgeMap edge_map_;
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators_;  // made on first use
  std::optional<Point2i> inner_;
  std::optional<Features> last_good_;
  Point2d velocity_;
  double limit_ = 0;  // the area limit of the current frame's estimate  // of the centroid between
                      // the last two accepted frames, px per frame
  double area0_ = 0;
  int refused_in_a_row_ = 0;
  Pose pose_, raw_pose_;
  OneEuroFilter fx_, fy_, fdepth_;
  PushDetector push_;
  MotionDetector motion_;
  Acquisition last_acquisition_ = Acquisition::Auto;
  MotionDetector::Motion moved_;
};

}  // namespace projtrack
