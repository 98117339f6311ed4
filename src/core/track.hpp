// Where the track stands between frames: what every object model may read of it (the tracker's
// state, tracker/tracker_state.hpp, holds it and alone changes it, through its named
// transitions).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>

#include "projtrack/features.hpp"
#include "projtrack/geometry.hpp"

namespace projtrack {

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
  bool seeded = false;         // the track started from the user's point, box or mask
  // The object when its last track was dropped: a model may look for it again near there.
  double lost_area = 0;
  Point2d lost_centroid;
};

}  // namespace projtrack
