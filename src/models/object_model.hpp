// An object model: what the tracker knows of the object between frames, and how it finds the
// object on a new frame. The tracker (src/tracker/) holds one, made from the table
// (include/projtrack/object_model_table.def, make_object_model()), and never asks which: it gives
// the model the frame's evidence and the track, takes the model's observation (a silhouette, or
// an estimate made on the edges), runs the estimator on a silhouette, judges the estimate with the
// rule every model shares (core/plausibility's why_refused) and the model's own veto, and tells
// the model its verdict (settle()). Each model lives in its own folder, src/models/<name>/, and
// owns its state, buffers and parameters (TrackerParams' member of its own).
#pragma once

#include <cmath>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/frame_pixels.hpp"
#include "core/mask.hpp"
#include "core/track.hpp"
#include "models/frame_evidence.hpp"
#include "projtrack/features.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/silhouette_mask.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

// Where a new object is, as the user (or nobody) said; or, for Lost, the track's own object that
// the model lost mid-track (its silhouette gone), to be found again near `point` (the track's
// inner point) before the track is dropped.
struct StartRequest {
  enum class From { Nothing, Point, Box, Mask, Lost };
  From from = From::Nothing;
  // Point: the point; Box: the box's centre; Mask: the mask's deepest point; Lost: where the
  // track's next estimate would start. The estimator starts from it.
  Point2i point;
  Rect box;                       // Box and Mask: the box (of the mask)
  const cv::Mat* mask = nullptr;  // Mask: CV_8U at the frame's size, non-zero on the object
  // The user's own start (a point, box or mask they gave); false for a point the tracker chose
  // (Acquisition::Center's frame centre) and for Nothing.
  bool by_user = false;
};

// What a model made of a frame.
struct Observation {
  enum class Kind {
    Silhouette,  // the object's silhouette: the tracker runs the estimator on it
    Estimate,    // an estimate already made (the edges model's, on the edges)
    Missing,     // nothing of the object was found (`why`)
    Stopped,     // the frame's work ran out or was interrupted before anything was found
  };
  Kind kind = Kind::Missing;
  const Mask* silhouette = nullptr;  // Silhouette: in work coordinates at `scale`
  int scale = 1;
  Features estimate;     // Estimate: this frame's; Stopped: what stopped it (its status, detail)
  std::string why;       // Missing: why
  bool resumed = false;  // a start found an object lost before again, by its model
  // The area the estimate's fills stopped at (EstimateOptions::area_limit): the refusal of an
  // estimate above it says "not filled" rather than how far it jumped.
  double area_limit = HUGE_VAL;

  static Observation missing(std::string why) {
    Observation o;
    o.why = std::move(why);
    return o;
  }
  static Observation stopped(Features what = {}) {
    Observation o;
    o.kind = Kind::Stopped;
    o.estimate = std::move(what);
    return o;
  }
  static Observation of_silhouette(const Mask& s, int scale, bool resumed = false) {
    Observation o;
    o.kind = Kind::Silhouette;
    o.silhouette = &s;
    o.scale = scale;
    o.resumed = resumed;
    return o;
  }
};

// A model's own reason to refuse an estimate the shared rule accepts (empty `why`: none), and
// whether the track ends at once.
struct Veto {
  std::string why;
  bool drop = false;
};

// What the tracker made of the model's last observation.
enum class Verdict {
  Accepted,  // the object, measured: the model may learn from this frame
  Refused,   // not the object (or not plausibly): the track goes on from what the model knew
  Stopped,   // the frame's work ran out or was interrupted: nothing of this frame counts
};

// What a dropped track keeps of the object.
enum class Forget {
  Position,    // where it was; its model (colours) stays, to find it again
  Everything,  // all of it: a new object next
};

class ObjectModel {
 public:
  virtual ~ObjectModel() = default;

  // Whether the model follows an object (follow()), or needs a start (start()).
  virtual bool tracking() const = 0;
  // A new object on this frame, where `request` says. `track` is the track this start begins or
  // (after rescale() or relearn() that lost the model's silhouette) continues.
  virtual Observation start(FrameEvidence& ev, const StartRequest& request, const Track& track) = 0;
  // The followed object on this frame.
  virtual Observation follow(FrameEvidence& ev, const Track& track) = 0;
  // The model's own veto on `f`, this frame's estimate of its observation, which the shared rule
  // accepts (default: none).
  virtual Veto veto(FrameEvidence& ev, const Features& f, const Track& track);
  // The tracker's verdict on this frame's observation: a model learns from accepted frames only.
  virtual void settle(Verdict verdict) = 0;
  // The frames are now sx × sy times as large, width × height. False when the model cannot
  // follow its object across the change: the tracker then starts it again within the object's
  // last box.
  virtual bool rescale(double sx, double sy, int width, int height) = 0;
  // The frames' colours are read another way (another format, same size): what the model learned
  // of the colours no longer holds. False as rescale().
  virtual bool relearn() = 0;
  // The track was dropped or reset.
  virtual void forget(Forget what) = 0;
  // The object's silhouette after the last frame (empty when the model holds none); between an
  // observation and its verdict, the observation's.
  virtual SilhouetteMask silhouette(int frame_width, int frame_height) const;

  // Where this frame's observation meets another object's (a MultiTracker), between the
  // observation and its verdict. explains: how well the model's own evidence of this frame (what
  // it sees of the object there, not where it expected it) takes `pixels` for its object, a mean
  // log-odds; -infinity when it has no such evidence (a start, or no silhouette: the default).
  // give_up: the observation `o` without `pixels`, which the object in front owns (missing when
  // nothing is left); the default has no silhouette to give up and returns `o`.
  virtual double explains(const FramePixels& pixels) const;
  virtual Observation give_up(const FramePixels& pixels, const Observation& o);
};

// The model of `kind`, made from the table's row (src/models/model_table.cpp).
std::unique_ptr<ObjectModel> make_object_model(ObjectModelKind kind);

// Each model's folder defines its row's factory.
template <ObjectModelKind kind>
std::unique_ptr<ObjectModel> make_object_model();

}  // namespace projtrack
