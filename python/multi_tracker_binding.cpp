// The MultiTracker class as Python sees it: Tracker's keywords and max_objects, add/remove by id,
// track() -> {id: Result}, and OpenCV's legacy MultiTracker.update().
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "projtrack/names.hpp"
#include "py_multi_tracker.hpp"

namespace projtrack::python {

namespace py = pybind11;

namespace {

std::string class_doc() {
  return "A tracker of several objects in one sequence of numpy frames, each with its id (from 1,\n"
         "never reused): add() starts one, track() returns {id: Result}, update() OpenCV's legacy\n"
         "MultiTracker's (ok, boxes). One frame's edges, motion and work budget serve every\n"
         "object; an object hidden behind another is reported 'occluded' with its last "
         "features.\n\n"
         "Settings (keywords only) are Tracker's (docs/python.md), and max_objects, the most\n"
         "objects followed at once. Defaults:\n" +
         keywords_doc(multi_defaults());
}

std::unique_ptr<PyMultiTracker> make(const py::kwargs& kwargs) {
  return std::make_unique<PyMultiTracker>(options_from(kwargs, multi_defaults(), "MultiTracker"));
}

int add(PyMultiTracker& t, const py::handle& frame, const py::object& where,
        const py::object& point, const py::object& box, const py::object& mask) {
  const Where start = one_of({{given(where), Where::Either},
                              {given(point), Where::Point},
                              {given(box), Where::Box},
                              {given(mask), Where::Mask}});
  if (start.kind == Where::Nowhere)
    throw py::type_error(
        "add() needs where the object is: point=(x, y), box=(x, y, w, h) or "
        "mask=array");
  return t.add(frame, start);
}

}  // namespace

void bind_multi_tracker(py::module_& m) {
  py::class_<PyMultiTracker>(m, "MultiTracker", class_doc().c_str())
      .def(py::init(&make))
      .def("add", &add, py::arg("frame"), py::arg("where") = py::none(), py::kw_only(),
           py::arg("point") = py::none(), py::arg("box") = py::none(), py::arg("mask") = py::none(),
           "A new object on `frame` (whose size it gives): box=(x, y, w, h) around it, point=\n"
           "(x, y) inside it, or mask=an (H, W) array non-zero on it (any numeric dtype, as\n"
           "Tracker's); or `where`, any of the three. Returns its id. It is tracked from the next\n"
           "frame given to track() or update(): give it `frame` again to start there. ValueError\n"
           "when refused: outside the frame, empty, max_objects followed, or on an object\n"
           "followed already.")
      .def("remove", &PyMultiTracker::remove, py::arg("id"),
           "Stops following object `id` (ValueError when there is none). Its id is not reused.")
      .def("clear", &PyMultiTracker::clear, "Stops following every object (ids go on).")
      .def_property_readonly("ids", &PyMultiTracker::ids,
                             "The ids of the objects followed, in the order they were added.")
      .def("__len__", &PyMultiTracker::size)
      .def("__contains__",
           [](PyMultiTracker& t, const py::handle& id) {
             const std::vector<int> ids = t.ids();
             return py::isinstance<py::int_>(id) &&
                    std::find(ids.begin(), ids.end(), id.cast<int>()) != ids.end();
           })
      .def("mask", &PyMultiTracker::mask, py::arg("id"),
           "Object `id`'s silhouette after the last frame, as Tracker's Result.mask: (H, W)\n"
           "uint8, 255 on it; None when it has none. ValueError for an unknown id.")
      .def("track", &PyMultiTracker::track, py::arg("frame"), py::kw_only(),
           py::arg("t") = py::none(), py::arg("mask") = true,
           "{id: Result} for one frame, in the order of ids; each Result has its .id. `t`: the\n"
           "frame's time in seconds (default: frames counted at fps). `mask`: whether to draw\n"
           "each silhouette's mask (Result.mask).")
      .def("update", &PyMultiTracker::update, py::arg("frame"),
           "(ok, boxes), as OpenCV's legacy MultiTracker: ok when every object was measured on\n"
           "this frame; boxes a float64 array of shape (N, 4), one (x, y, w, h) per object in the\n"
           "order of ids (an object not measured: its last box; (0, 0, 0, 0) before any).")
      .def_property_readonly(
          "max_objects", [](const PyMultiTracker& t) { return t.options().max_objects; },
          "The most objects followed at once.")
      .def_property_readonly(
          "settings", [](const PyMultiTracker& t) { return options_dict(t.options()); },
          "The settings, as a dict keyed by the keywords MultiTracker(...) takes.")
      .def_property_readonly("frames", &PyMultiTracker::frames, "Frames tracked since the start.")
      .def("__repr__", [](PyMultiTracker& t) {
        const Settings& s = t.options().settings;
        return "<projtrack.MultiTracker objects=" + std::to_string(t.size()) + " method='" +
               nick_of(s.method) + "' object_model='" + nick_of(s.tracker.model) + "'>";
      });
}

}  // namespace projtrack::python
