#include "result.hpp"

#include <string>

#include "projtrack/gesture.hpp"
#include "projtrack/status.hpp"

namespace projtrack::python {

namespace py = pybind11;

namespace {

// A value of the features, or None when the library reports none (no object measured yet).
template <class F>
py::object if_features(const Result& res, F value) {
  return res.r.features.valid() ? py::object(value(res.r.features)) : py::none();
}

py::tuple box(const Rect& b) { return py::make_tuple(b.x, b.y, b.width, b.height); }

std::string describe(const Result& res) {
  std::string s = "<projtrack.Result " + std::string(status_name(res.r.status));
  if (res.r.id != 0) s += " id=" + std::to_string(res.r.id);
  if (res.r.features.valid()) {
    const Features& f = res.r.features;
    s += (res.ok() ? "" : " (held)") + std::string(" centroid=(") +
         py::str(py::float_(f.centroid.x)).cast<std::string>() + ", " +
         py::str(py::float_(f.centroid.y)).cast<std::string>() +
         ") area=" + std::to_string(static_cast<long long>(f.area));
  }
  if (!res.r.detail.empty()) s += " detail='" + res.r.detail + "'";
  return s + ">";
}

}  // namespace

void bind_result(py::module_& m) {
  py::class_<Pose>(m, "Pose",
                   "The 3D pointer: x and y in [-1, 1] (0 at the frame's centre, +1 at "
                   "its right and bottom edges), depth the square root of the object's share of "
                   "the frame, rising as "
                   "the object nears the camera.")
      .def_readonly("x", &Pose::x)
      .def_readonly("y", &Pose::y)
      .def_readonly("depth", &Pose::depth)
      .def("__iter__", [](const Pose& p) { return py::iter(py::make_tuple(p.x, p.y, p.depth)); })
      .def("__repr__", [](const Pose& p) {
        return "Pose(x=" + py::repr(py::float_(p.x)).cast<std::string>() +
               ", y=" + py::repr(py::float_(p.y)).cast<std::string>() +
               ", depth=" + py::repr(py::float_(p.depth)).cast<std::string>() + ")";
      });

  py::class_<Result>(m, "Result",
                     "What the tracker made of one frame (Tracker.track), or of one object's "
                     "(MultiTracker.track)")
      .def_property_readonly(
          "id", [](const Result& r) { return r.r.id; },
          "the object's id in a MultiTracker (from 1); 0 from a Tracker")
      .def_property_readonly(
          "status", [](const Result& r) { return std::string(status_name(r.r.status)); },
          "'ok', 'reached-border', 'covers-frame' (measured), 'lost', "
          "'occluded' (hidden behind another object), 'searching', 'no-inner-point', "
          "'invalid-parameters', ...")
      .def_property_readonly("ok", &Result::ok,
                             "True when the features were measured on this frame")
      .def_property_readonly(
          "detail", [](const Result& r) { return r.r.detail; },
          "why, when the status is not a measurement")
      .def_property_readonly(
          "acquired", [](const Result& r) { return r.r.acquired; },
          "tracking (re)started on this frame")
      .def_property_readonly(
          "centroid",
          [](const Result& r) {
            return if_features(
                r, [](const Features& f) { return py::make_tuple(f.centroid.x, f.centroid.y); });
          },
          "(x, y) px; a 'lost' result repeats the last measured one; None before any")
      .def_property_readonly(
          "area",
          [](const Result& r) {
            return if_features(r, [](const Features& f) { return py::float_(f.area); });
          },
          "px²; as centroid")
      .def_property_readonly(
          "box",
          [](const Result& r) {
            return if_features(r, [](const Features& f) { return box(f.bbox); });
          },
          "(x, y, width, height) of the object's pixels; as centroid")
      .def_property_readonly(
          "inner_point",
          [](const Result& r) {
            return r.r.inner_point
                       ? py::object(py::make_tuple(r.r.inner_point->x, r.r.inner_point->y))
                       : py::none();
          },
          "(x, y): where the next frame's estimate starts; None when not tracking")
      .def_property_readonly(
          "pose", [](const Result& r) { return r.r.has_pose ? py::cast(r.r.pose) : py::none(); },
          "the smoothed 3D pointer (Pose), or None without an object")
      .def_property_readonly(
          "raw_pose",
          [](const Result& r) { return r.r.has_pose ? py::cast(r.r.raw_pose) : py::none(); },
          "the pointer before smoothing")
      .def_property_readonly(
          "gesture",
          [](const Result& r) {
            return r.r.gesture == Gesture::None ? py::none()
                                                : py::cast(std::string(gesture_name(r.r.gesture)));
          },
          "'push' (a click), 'press' or 'release' (a drag) completed on this frame, else None")
      .def_property_readonly(
          "push", [](const Result& r) { return r.r.gesture == Gesture::Push; },
          "a push toward the camera (a click) completed on this frame")
      .def_property_readonly(
          "mask", [](const Result& r) { return r.mask; },
          "the silhouette: (H, W) uint8, 255 on the object, 0 elsewhere, as "
          "centroid; None with the edges model or without an object")
      .def_property_readonly(
          "work", [](const Result& r) { return r.r.work; }, "the work this frame did (work units)")
      .def_property_readonly(
          "work_limit", [](const Result& r) { return r.r.work_limit; },
          "the frame's budget of work")
      .def("__repr__", &describe);
}

}  // namespace projtrack::python
