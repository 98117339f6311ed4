// What a user can set on the element (its properties, signals and clicks), as the streaming thread
// reads it: one copy per frame, taken under the object lock.
#pragma once

#include <vector>

#include "projtrack/geometry.hpp"
#include "projtrack/names.hpp"
#include "projtrack/settings.hpp"

namespace projtrack::gst {

// Which frames post a projtrack message (as facedetect's `updates`). Names: updates_table.def.
enum class Updates {
  EveryFrame,  // every frame
  OnChange,    // the status changes, an object is acquired, or a gesture is found
  None,        // never
};

// What the overlay draws (draw-flags): a bit each, all by default. Names: draw_flags_table.def.
enum DrawFlag : unsigned {
  kDrawStatus = 1u << 0,      // the text panel: the status and why, x, y, depth, the method
  kDrawOutline = 1u << 1,     // the silhouette's outline
  kDrawBox = 1u << 2,         // the bounding box
  kDrawCentroid = 1u << 3,    // the centroid's cross
  kDrawInnerPoint = 1u << 4,  // the inner point for the next frame
  kDrawGrid = 1u << 5,        // what the method did: grid lines, filled pixels, blocks, rays
  kDrawAll = (1u << 6) - 1,
};

// Everything a user can set: the library's settings bundle (its defaults are the properties'),
// and what only the element has. A default-constructed ElementSettings holds every property's
// default.
struct ElementSettings : Settings {
  bool draw = false;
  unsigned draw_flags = kDrawAll;
  bool alpha_mask = false;  // the silhouette into the alpha channel, when the format has one
  bool post_messages = true;
  Updates updates = Updates::EveryFrame;
  int inner_point_x = -1,
      inner_point_y = -1;  // the last inner point given (property, signal, click); -1 = none
  Rect start_box;          // the last box given (start-box, track-box); empty = none
  // Several objects at once (a MultiTracker beside the single track above, ids from 1): the
  // starts given by start-boxes and start-points, how many may be followed, whether a click adds
  // one, and whose silhouettes alpha-mask cuts out (0: the single track's; empty: all).
  std::vector<Rect> start_boxes;
  std::vector<Point2i> start_points;
  int max_objects = 8;
  bool click_adds = false;
  std::vector<int> alpha_ids;
};

// The most objects max-objects allows (its range's top).
inline constexpr int kMaxObjects = 64;

// What the streaming thread must do to the track before the next frame.
enum class SeedCommand { None, Seed, SeedBox, Reset };

}  // namespace projtrack::gst
