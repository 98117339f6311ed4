// The Tracker class as Python sees it: keyword settings, OpenCV's init/update pair, and track().
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "projtrack/names.hpp"
#include "py_tracker.hpp"

namespace projtrack::python {

namespace py = pybind11;

namespace {

// The class's docstring: what it is, then every keyword and its default (keyword_table.def).
std::string class_doc() {
  return "A tracker of one object in a sequence of numpy frames (gray (H, W) or BGR (H, W, 3) "
         "uint8).\n\n"
         "Settings (keywords only) are named as the element's properties, with _ for -, and\n"
         "mean what they mean there (docs/element.md, docs/python.md); `model`, `edge_low` and\n"
         "`edge_high` are also taken for object_model, edge_threshold_low and\n"
         "edge_threshold_high. fps is the frames' rate when track() is given no time. A bad\n"
         "setting raises ValueError; a wrong type or an unknown keyword TypeError. Defaults:\n" +
         keywords_doc();
}

std::unique_ptr<PyTracker> make(const py::kwargs& kwargs) {
  return std::make_unique<PyTracker>(options_from(kwargs));
}

}  // namespace

void bind_tracker(py::module_& m) {
  py::class_<PyTracker>(m, "Tracker", class_doc().c_str())
      .def(py::init(&make))
      .def("init", &PyTracker::init, py::arg("frame"), py::arg("where"),
           "Starts a new object on `frame`: `where` is a box (x, y, w, h) around it, as OpenCV's\n"
           "trackers take, a point (x, y) inside it, or a mask: an (H, W) array, non-zero on it. "
           "True when the object was measured on\n"
           "this frame (else the tracker goes on trying from there for a few frames).")
      .def("update", &PyTracker::update, py::arg("frame"),
           "(ok, (x, y, w, h)), as OpenCV's trackers: ok when the object was measured on this\n"
           "frame, with its box; (False, (0, 0, 0, 0)) otherwise.")
      .def(
          "track",
          [](PyTracker& t, const py::handle& frame, const py::object& point, const py::object& box,
             const py::object& time, const py::object& mask) {
            // `mask`: True or False draws the result's mask or not; an array starts from it.
            const bool start_mask = !py::isinstance<py::bool_>(mask);
            const Where where =
                one_of({{given(point), Where::Point},
                        {given(box), Where::Box},
                        {start_mask ? py::handle(mask) : py::handle(), Where::Mask}});
            return t.track(frame, where, time, start_mask || mask.cast<bool>());
          },
          py::arg("frame"), py::kw_only(), py::arg("point") = py::none(),
          py::arg("box") = py::none(), py::arg("t") = py::none(), py::arg("mask") = py::bool_(true),
          "The Result of one frame. With `point` (x, y) or `box` (x, y, w, h), a new object\n"
          "from there on this frame. `t`: the frame's time in seconds (default: frames counted\n"
          "at fps). `mask`: whether to draw the silhouette's mask (Result.mask), or an (H, W)\n"
          "array non-zero on the object: a new object from that silhouette on this frame.")
      .def("reset", &PyTracker::reset, "Forgets the object (and restarts the frames' time).")
      .def_property_readonly(
          "settings", [](const PyTracker& t) { return options_dict(t.options()); },
          "The tracker's settings, as a dict keyed by the keywords Tracker(...) takes.")
      .def_property_readonly("frames", &PyTracker::frames, "Frames tracked since the start.")
      .def("__repr__", [](const PyTracker& t) {
        const Settings& s = t.options().settings;
        return "<projtrack.Tracker method='" + std::string(nick_of(s.method)) + "' object_model='" +
               nick_of(s.tracker.model) + "'>";
      });
}

}  // namespace projtrack::python
