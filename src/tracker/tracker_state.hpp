// Everything the tracker keeps from one frame to the next, in one place, and the named
// transitions that are the only ways the track changes. The stages' own memories (the pointer's
// filters, the object model's colours, the finder's background, the motion detectors' last
// frames) are held here too and change through their own interfaces; which of them a transition
// touches is said here, once.
#pragma once

#include <cstdint>
#include <optional>

#include "acquisition/motion_acquisition.hpp"
#include "acquisition/motion_detector.hpp"
#include "acquisition/object_finder.hpp"
#include "appearance/silhouette_model.hpp"
#include "pointer/pointer.hpp"
#include "projtrack/exposure.hpp"
#include "projtrack/features.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/tracker_params.hpp"
#include "segmentation/flow_segmenter.hpp"

namespace projtrack {

class TrackerState {
 public:
  // Where the track stands.
  struct Track {
    std::optional<Point2i> inner;  // where the next estimate starts (none: no track)
    std::optional<Rect> seed_box;  // the user's box, until the track starts from it
    cv::Mat seed_mask;             // the user's mask (frame size), until the track starts from it
    std::optional<Features> last;  // the last accepted estimate
    Point2d velocity;              // of the centroid between the last two accepted frames, px
    // The frames changed size or format since the last accepted one: the stream may have been
    // cut there (a clip joined to another), so the centroid's step across it is no velocity.
    bool across_change = false;
    int accepted = 0;            // frames accepted since the track started
    int refused_in_a_row = 0;    // refused frames since the last accepted one
    std::uint32_t refusals = 0;  // a bit per frame since the track started, newest lowest
    bool seeded = false;         // the track started from the user's point or box
    int still = 0;               // frames in a row the object looked like the background
    // The object when its last track was dropped: found again by its colours near there.
    double lost_area = 0;
    Point2d lost_centroid;
    int searched = 0;  // frames searched since
  };
  const Track& track() const { return track_; }
  ObjectModelKind model() const { return model_; }

  // The stages' memories between frames.
  Pointer pointer;
  SilhouetteModel object;               // the appearance model's object
  FlowSegmenter flow;                   // the flow model's object
  ObjectFinder finder;                  // the appearance model's search, and the scene's background
  MotionDetector motion;                // the appearance model's frame differencing
  MotionDetector::Motion moved;         // the last frame's motion
  MotionDetector::Motion moved_before;  // of the last frame before it that showed motion
  MotionAcquisition edges_acquisition;  // the edges model's search
  Exposure exposure;                    // how the appearance model reads frames

  // The user's point or box: a new object, tracked from there on the next frame.
  void seed(Point2i p);
  void seed_box(const Rect& box);
  // The user's mask (CV_8U, frame size, non-zero on the object), with its box and deepest point.
  void seed_mask(const cv::Mat& mask, const Rect& box, Point2i deepest);
  // Forgets the object and its colours: acquisition starts over.
  void reset();
  // Ends the track (a press held is released); with Keep::Colours the object's colours stay
  // known, to find it again (the appearance model). The motion history starts afresh either way.
  enum class Keep { Nothing, Colours };
  void drop(Keep keep);
  // Another object model: the same object (its inner point) found again its own way.
  void use_model(ObjectModelKind kind);
  // Takes `f` as this frame's estimate, at `t` seconds in a width × height frame; `resumed`: the
  // object found again by its colours. True when a track (re)starts here.
  bool accept(const Features& f, bool resumed, double t, int width, int height,
              const TrackerParams& tp);
  // One more refused frame: the last accepted estimate stays; a gesture in progress does not.
  void refuse();
  // Acquisition searched this frame.
  void count_search() { ++track_.searched; }
  // Whether the tracked object looked like the scene's background on this frame: counts such
  // frames in a row (forget_still() starts the count over).
  int note_still(bool still) { return track_.still = still ? track_.still + 1 : 0; }
  void forget_still() { track_.still = 0; }
  // The colours of an object lost long ago: acquisition looks for any object again.
  void forget_colours();
  // The frames are now sx × sy times as large: the track's points, boxes and areas follow, and
  // the appearance model's silhouette with its colours; the flow model's object is found again
  // within its box (relearn()).
  void rescale(double sx, double sy);
  // The frames' colours are read another way: the object model forgets its colours and silhouette
  // and starts again within the last box on the next frame; the track (its last estimate, its
  // inner point, the pointer) goes on, so that start is no new acquisition.
  void relearn();

 private:
  Track track_;
  ObjectModelKind model_ = ObjectModelKind::Appearance;
};

}  // namespace projtrack
