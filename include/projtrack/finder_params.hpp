// How the appearance model finds an object's first silhouette (ObjectFinder,
// src/acquisition/object_finder.hpp): part of TrackerParams.
#pragma once

namespace projtrack {

struct FinderParams {
  // The frame's border strip, as a share of its smaller side (at least 4 px): what is seen there
  // is background. A colour counts as seen there from this share of the strip's pixels on.
  double border = 0.04;
  double border_share = 0.0007;
  // A candidate must fill at least this share of the frame, and at most max_area.
  double min_area = 0.002;
  double max_area = 0.5;
  // A candidate found by motion or by colour must have at least this share of its sampled
  // pixels moving: a static region (the background, a table) is never taken for the object.
  double min_moving = 0.02;
  // ... or at least this share of the band along its outline (3 work pixels wide): an evenly
  // coloured object that moves a little changes only along its outline, which a static region
  // does not (the frame's noise changes a few per cent of any band).
  double min_moving_outline = 0.05;
  // The finder reads the whole frame at a scale that makes it about this many work pixels.
  double work_pixels = 80000;
  // The scene's background: the running mean of the frames searched (at this rate a frame, after
  // `background_frames` frames). A candidate must differ from it (by more than
  // `background_change` grey levels) on at least `min_foreground` of its pixels: a static region
  // — a sign a passer-by walked in front of — is the background, whatever moved around it.
  double background_rate = 1.0 / 16;
  int background_frames = 8;
  int background_change = 15;
  double min_foreground = 0.15;
};

}  // namespace projtrack
