// Every tracker over one clip, frame by frame, and the element's speed on the clip at 1080p.
#pragma once

#include <cstdio>

#include "clip.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace projtrack::bench {

// The runs on a clip with a truth: the element with every method seeded at the deepest point of
// the first frame's true silhouette (on a variant: the default method alone), the default method
// at each quarter point and from the true box (`start-box`), with no seed, and the box trackers
// from the true box. Without a truth: the element with no seed alone. The trackers' order is
// rotated on every frame so a noisy machine slows all of them alike.
void run_all(const Clip& c, RunsCsv& out, Progress& progress, bool only_default);

// The clip scaled to 1920×1080: the element (default method, at the deepest point) beside a copy
// of the frame and the harness alone, frame by frame in turn; a row each in `speed_csv`.
void speed_1080p(const Clip& c, std::FILE* speed_csv, Progress& progress);

}  // namespace projtrack::bench
