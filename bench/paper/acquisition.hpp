// projtrack-bench's auto-acquisition section: acquisition.csv.
#pragma once

#include <ostream>

#include "options.hpp"
#include "progress.hpp"

namespace projtrack::bench {

// Auto acquisition: the original system's rule (the centroid of the changed pixels) against ours
// (the most compact closed region among seeds where the frame changed), on moving objects.
// One row per sequence, instance and strategy.
void acquisition(const Options& opt, std::ostream& csv, Progress& progress);

}  // namespace projtrack::bench
