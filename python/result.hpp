// What one frame came to, for Python: the library's TrackResult and the silhouette's mask.
#pragma once

#include <pybind11/numpy.h>

#include "projtrack/tracker.hpp"

namespace projtrack::python {

struct Result {
  TrackResult r;
  pybind11::object mask = pybind11::none();  // (H, W) uint8, 255 on the object; or None

  // Features measured on this frame (a held "lost" result repeats the last measured ones).
  bool ok() const { return has_features(r.status); }
};

// The Result class and the Pose class in module `m`.
void bind_result(pybind11::module_& m);

}  // namespace projtrack::python
