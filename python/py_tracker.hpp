// The tracker for Python: numpy frames in, results out, with OpenCV's tracker API beside the
// library's (init(frame, box) then update(frame) -> (ok, box)).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "projtrack/tracker.hpp"
#include "result.hpp"
#include "seeds.hpp"
#include "settings.hpp"
#include "stream.hpp"

namespace projtrack::python {

class PyTracker {
 public:
  explicit PyTracker(const TrackerOptions& o) : options_(o), stream_(o.fps) {}

  // The library's frame: seeds from `where` when given, tracks `frame` at `t` seconds (None:
  // frames counted at the settings' fps); the silhouette's mask when `with_mask`.
  Result track(const pybind11::handle& frame, const Where& where, const pybind11::object& t,
               bool with_mask);
  // OpenCV's pair: a new object from `where` (a point (x, y) or a box (x, y, w, h)) on `frame`;
  // then (ok, (x, y, w, h)) per frame, (False, (0, 0, 0, 0)) when nothing was measured.
  bool init(const pybind11::handle& frame, const pybind11::handle& where);
  pybind11::tuple update(const pybind11::handle& frame);
  void reset();

  const TrackerOptions& options() const { return options_; }
  long frames() const { return stream_.frames(); }

 private:
  TrackerOptions options_;
  Tracker tracker_;
  FrameStream stream_;
};

// The Tracker class in module `m`.
void bind_tracker(pybind11::module_& m);

}  // namespace projtrack::python
