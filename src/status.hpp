// What happened on one estimate: a result with features, or why there is none.
#pragma once

#include <string_view>

namespace projtrack {

enum class Status {
  // With features:
  Ok,             // the estimate stayed inside the frame
  ReachedBorder,  // it touches the frame border: the object is cut by the frame, or it leaked
  CoversFrame,    // it touches all four borders: no closed contour around the inner point
  // Without features of this frame (the tracker's verdicts):
  Lost,       // the estimate was refused (leaked, collapsed, or none); the last good one is kept
  Searching,  // automatic acquisition is looking for an object to track
  // Without features:
  NoInnerPoint,       // nothing to track yet: no inner point was given
  InnerPointOutside,  // the inner point is farther outside the frame than the seed radius
  InnerPointOnEdge,   // the inner point and every pixel within the seed radius are edges
  EmptyImage,         // zero width or height, or no pixels
  InvalidImage,       // stride smaller than the width
  InvalidParameters,  // a parameter out of range (see validate())
};

// Short lower-case name, as in GStreamer messages and CSV files ("ok", "reached-border", ...). The
// view is of a string literal, so data() is null-terminated (usable as a C string).
std::string_view status_name(Status s);
// Whether the result carries a centroid, an area and a bounding box.
inline bool has_features(Status s) {
  return s == Status::Ok || s == Status::ReachedBorder || s == Status::CoversFrame;
}

}  // namespace projtrack
