// How brightly a frame is exposed (luma_range: the motion detector reads a frame's spread), and
// how a dim one could be read: a camera in dim light squeezes every colour toward black and
// neutral, so that colours it told apart in good light fall into the same colour bins (a dark
// cup and the shadowed hand that holds it). exposure_for() was the appearance model's reading of
// a dim frame; since that model was removed no stage applies it.
#pragma once

#include <array>
#include <cstdint>

#include "image_view.hpp"

namespace projtrack {

// The 2nd and 98th percentiles of a frame's luma.
struct LumaRange {
  int lo = 0, hi = 255;
  int spread() const { return hi - lo; }
};

// The range of a histogram of luma samples.
LumaRange luma_range(const std::array<std::uint32_t, 256>& histogram);
// The range of `luma`, from samples on a grid at most `max_samples` strong.
LumaRange luma_range(const ImageView& luma, int max_samples = 16384);

// How colours are read: luma above `black` and chroma about neutral (128) multiplied by `gain`,
// as a brighter exposure would have shown them. The identity by default.
struct Exposure {
  double gain = 1;
  int black = 0;
  bool identity() const { return gain == 1; }
};

// The exposure that reads a dim frame of luma range `r` — one whose bright end (the 98th
// percentile) lies fewer than `dim` levels above black (the 2nd percentile, at most 16: video
// black) — as if its bright end lay `normal` levels above black: a gain of normal / (bright end -
// black), at most `max_gain` (more would only amplify noise); the identity for any other frame. A
// frame's spread is no measure: a bright wall that fills it spans few levels, and is well exposed.
// Stretched to full light (`normal`), not just to the edge of dim: colours then fall into the
// colour bins they fall into in good light, wherever the light was between.
Exposure exposure_for(const LumaRange& r, double dim, double normal, double max_gain = 3);

}  // namespace projtrack
