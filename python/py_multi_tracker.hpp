// Several objects for Python: numpy frames in, one result per object out, each with its id; with
// OpenCV's legacy MultiTracker's update(frame) -> (ok, boxes) beside the library's track().
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "projtrack/multi_tracker.hpp"
#include "result.hpp"
#include "seeds.hpp"
#include "settings.hpp"
#include "stream.hpp"

namespace projtrack::python {

class PyMultiTracker {
 public:
  explicit PyMultiTracker(const TrackerOptions& o)
      : options_(o), tracker_(static_cast<std::size_t>(o.max_objects)), stream_(o.fps) {}

  // A new object from `where` (a point, a box or a mask) in `frame`'s pixels, tracked from the
  // next frame given to track() or update() (give it `frame` again to start there); its id. A
  // ValueError with the library's reason when refused (outside the frame, empty, max_objects
  // followed already, or on an object followed already).
  int add(const pybind11::handle& frame, const Where& where);
  // Stops following object `id`: a ValueError when there is none (ids are never reused).
  void remove(int id);
  void clear();
  std::vector<int> ids();
  std::size_t size();
  // Object `id`'s silhouette after the last frame as Tracker's Result.mask: (H, W) uint8, 255 on
  // it; None when it has none. A ValueError for an unknown id.
  pybind11::object mask(int id);
  // {id: Result} for `frame` at `t` seconds (None: frames counted at fps), in the order of ids;
  // each Result's mask drawn when `with_mask`.
  pybind11::dict track(const pybind11::handle& frame, const pybind11::object& t, bool with_mask);
  // OpenCV's legacy MultiTracker.update: (ok, boxes), ok when every object was measured on this
  // frame, boxes an N × 4 float64 array of (x, y, w, h) in the order of ids (an object not
  // measured: its last box, as OpenCV keeps it; (0, 0, 0, 0) before any).
  pybind11::tuple update(const pybind11::handle& frame);

  const TrackerOptions& options() const { return options_; }
  long frames() const { return stream_.frames(); }

 private:
  // The results of `frame`, with their masks when `with_mask`.
  std::vector<Result> results(const pybind11::handle& frame, const pybind11::object& t,
                              bool with_mask);

  TrackerOptions options_;
  MultiTracker tracker_;
  FrameStream stream_;
};

// The MultiTracker class in module `m`.
void bind_multi_tracker(pybind11::module_& m);

}  // namespace projtrack::python
