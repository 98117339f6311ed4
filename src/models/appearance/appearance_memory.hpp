// What the appearance model keeps between frames: the object's silhouette and colours, the
// finder (the scene's background, the regions a new object is looked for in), the frame
// differencing that tells what moves, and how the frames are read (a dim scene stretched).
#pragma once

#include <string>

#include "acquisition/motion_detector.hpp"
#include "acquisition/object_finder.hpp"
#include "appearance/silhouette_model.hpp"
#include "core/mask.hpp"
#include "core/track.hpp"
#include "edges/edge_source.hpp"
#include "models/object_model.hpp"
#include "projtrack/color_view.hpp"
#include "projtrack/exposure.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack {

struct AppearanceMemory {
  SilhouetteModel object;               // the object: its silhouette and colours
  ObjectFinder finder;                  // the search, and the scene's background
  MotionDetector motion;                // frame differencing
  MotionDetector::Motion moved;         // the last frame's motion
  MotionDetector::Motion moved_before;  // of the last frame before it that showed motion
  Exposure exposure;                    // how frames are read
  int searched = 0;                     // frames searched since the object was lost (or forgotten)
  int still = 0;  // frames in a row the tracked object looked like the background

  // The motion history starts afresh (frames of another size, a new track).
  void forget_motion();
};

// The grey-level thresholds of motion and of the background scaled to a scene whose luma spans
// `spread` levels (TrackerParams::full_contrast; MotionDetector::spread()).
MotionDetector::Params motion_params(const TrackerParams& tp, int spread);
FinderParams finder_params(const TrackerParams& tp, int spread);

// The first silhouette of an object on `frame` (as the model reads it), and the object model
// started (or resumed) on it: where `request` says (the user's point, box or mask's box), or for
// none by TrackerParams::acquisition: the frame centre, or where the colours of an object lost
// before are (`track`'s lost_area, lost_centroid), or where the frame moves. A start without the
// user's point is vetoed when it runs into the frame's border or is the scene's background.
// `first` receives the finder's silhouette, `silhouette` the object model's.
struct AppearanceStart {
  bool found = false;
  bool resumed = false;  // the object lost before, found again by its colours
  std::string why;       // when not found
};
AppearanceStart start_appearance_track(AppearanceMemory& m, const ColorView& frame,
                                       EdgeSource& edges, const StartRequest& request,
                                       const Track& track, const TrackerParams& tp, Mask& first,
                                       Mask& silhouette);

// While tracking an object found without the user's point: whether it is a static region of the
// scene's background (its box hardly changes and its silhouette is what the background holds
// there) on this frame. Holds it (reported lost) for a few frames, then drops it. Updates the
// motion history with this frame.
enum class Stillness { Moves, Holds, Drop };
Stillness judge_stillness(AppearanceMemory& m, const ColorView& frame, const Features& f,
                          const Mask& silhouette, const TrackerParams& tp);

}  // namespace projtrack
