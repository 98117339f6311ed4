// The two kinds of status: what one estimate came to (EstimateStatus, in Features), and where the
// tracker stands after one frame (TrackStatus, in TrackResult). Data flows one way: an estimator
// never says a track is lost; the tracker reports an estimate's outcome as its own status when it
// takes the estimate as it is (reported_status), under the same name.
#pragma once

#include <string_view>

namespace projtrack {

// What happened on one estimate: features, or why there are none.
enum class EstimateStatus {
  // With features:
  Ok,             // the estimate stayed inside the frame
  ReachedBorder,  // it touches the frame border: the object is cut by the frame, or it leaked
  CoversFrame,    // it touches all four borders: no closed contour around the inner point
  // Without features:
  InnerPointOutside,  // the inner point is farther outside the frame than the seed radius
  InnerPointOnEdge,   // the inner point and every pixel within the seed radius are edges
  EmptyImage,         // zero width or height, or no pixels
  InvalidImage,       // stride smaller than the width
  InvalidParameters,  // a parameter out of range (see validate())
  // Stopped before the end (EstimateOptions::budget), without features:
  OverBudget,   // the work budget ran out
  Interrupted,  // the budget's stop flag was set (the caller is stopping)
};

// Where the tracker stands after one frame: tracking with this frame's features, its verdict on
// the frame, or why it could not look at it.
enum class TrackStatus {
  // Tracking, with this frame's features (the accepted estimate's own status):
  Ok,             // the object is inside the frame
  ReachedBorder,  // it touches the frame border
  CoversFrame,    // it touches all four borders
  // The tracker's verdicts, without features of this frame:
  Lost,          // this frame's estimate was refused (leaked, collapsed, or none); the last
                 // accepted one is kept
  Searching,     // automatic acquisition is looking for an object to track
  NoInnerPoint,  // nothing to track: no inner point was given and acquisition is manual
  // The frame or the settings could not be used (the estimate's status, or the tracker's own
  // checks); the track waits:
  EmptyImage,         // zero width or height, or no pixels
  InvalidImage,       // stride smaller than the width, or the frame and its edges differ in size
  InvalidParameters,  // a parameter out of range, or settings that conflict
  // The frame's work ran out (TrackerParams::max_work) before it came to an estimate: not a
  // measurement, so it counts as a refused frame (as Lost: the last accepted features are kept,
  // and `patience` of them in a row drop the track); acquisition searches again on the next frame.
  OverBudget,
  // The work was stopped (Tracker::set_stop_flag: the pipeline is stopping or flushing): the
  // track is kept as it was, untouched.
  Interrupted,
  // Another object followed by the same MultiTracker is in front of this one: its last accepted
  // features are kept (none of the other's pixels are given to it), and the frame does not count
  // towards dropping the track; it is found again when it comes out.
  Occluded,
};

// Short lower-case name, as in GStreamer messages and CSV files ("ok", "reached-border", ...). The
// view is of a string literal, so data() is null-terminated (usable as a C string). An estimate's
// outcome and the tracker's status that reports it (reported_status) have the same name.
std::string_view status_name(EstimateStatus s);
std::string_view status_name(TrackStatus s);
// The last value of each, for loops over every status.
inline constexpr EstimateStatus kLastEstimateStatus = EstimateStatus::Interrupted;
inline constexpr TrackStatus kLastTrackStatus = TrackStatus::Occluded;

// Whether the result carries a centroid, an area and a bounding box of this frame.
inline bool has_features(EstimateStatus s) {
  return s == EstimateStatus::Ok || s == EstimateStatus::ReachedBorder ||
         s == EstimateStatus::CoversFrame;
}
inline bool has_features(TrackStatus s) {
  return s == TrackStatus::Ok || s == TrackStatus::ReachedBorder || s == TrackStatus::CoversFrame;
}

// The tracker's status for an estimate it takes as it is: accepted (Ok, ReachedBorder,
// CoversFrame), failed for want of a usable frame or settings (EmptyImage, InvalidImage,
// InvalidParameters), or stopped (OverBudget, Interrupted). An estimate that found no free pixel
// at the inner point (InnerPointOutside, InnerPointOnEdge) is refused by the tracker: Lost.
TrackStatus reported_status(EstimateStatus s);

}  // namespace projtrack
