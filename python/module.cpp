// The Python module `projtrack`: the library's Tracker and MultiTracker on numpy frames.
#include <pybind11/pybind11.h>

#include "py_multi_tracker.hpp"
#include "py_tracker.hpp"
#include "result.hpp"
#include "settings.hpp"

namespace py = pybind11;
using namespace projtrack::python;

PYBIND11_MODULE(projtrack, m) {
  m.doc() =
      "projtrack: track objects in video from a point, box or mask of each, on numpy frames.\n\n"
      "    tracker = projtrack.Tracker()\n"
      "    tracker.init(frame, (x, y, w, h))      # or a point (x, y) inside the object\n"
      "    ok, box = tracker.update(next_frame)   # as OpenCV's trackers\n"
      "    result = tracker.track(frame)          # status, features, pose and silhouette\n\n"
      "    multi = projtrack.MultiTracker()       # several objects, each with its id\n"
      "    a = multi.add(frame, box=(x, y, w, h)); b = multi.add(frame, point=(x, y))\n"
      "    results = multi.track(frame)           # {id: Result}\n\n"
      "Frames are numpy arrays of uint8: gray (H, W) or BGR (H, W, 3), as OpenCV reads them.";
  m.attr("__version__") = PROJTRACK_VERSION;
  m.def(
      "methods",
      [] {
        py::list names;
        for (const projtrack::MethodInfo& info : projtrack::kMethods) names.append(info.nick);
        return names;
      },
      "The estimators' names, for Tracker(method=...).");
  bind_result(m);
  bind_tracker(m);
  bind_multi_tracker(m);
}
