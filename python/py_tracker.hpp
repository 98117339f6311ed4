// The tracker for Python: numpy frames in, results out, with OpenCV's tracker API beside the
// library's (init(frame, box) then update(frame) -> (ok, box)).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <mutex>

#include "frames.hpp"
#include "projtrack/tracker.hpp"
#include "result.hpp"
#include "settings.hpp"

namespace projtrack::python {

// Where init() or track() starts a new object: `obj` read as an inner point (x, y), a box
// (x, y, width, height), a mask ((H, W) array, non-zero on the object) or, for Either, whichever
// it is (a 2-D array: a mask; else by its count of numbers).
struct Where {
  enum Kind { Nowhere, Point, Box, Mask, Either };
  pybind11::handle obj;
  Kind kind = Nowhere;
  bool restart = false;  // init(): the frames' time starts over at 0 too
};

class PyTracker {
 public:
  explicit PyTracker(const TrackerOptions& o) : options_(o) {}

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
  long frames() const { return frames_; }

 private:
  // A frame of `width` × `height` with `channels` after the last one: the track follows a new size
  // or a new kind of frame as the element's does new caps.
  void reframe(int width, int height, int channels);

  TrackerOptions options_;
  Tracker tracker_;
  FrameReader reader_;
  int width_ = 0, height_ = 0, channels_ = 0;  // the last frame's (0: none yet)
  std::mutex mutex_;                           // one frame at a time: track() runs without the GIL
  // Frames tracked since the start or reset(); frames() may read it while a thread tracks.
  std::atomic<long> frames_{0};
};

// The Tracker class in module `m`.
void bind_tracker(pybind11::module_& m);

}  // namespace projtrack::python
