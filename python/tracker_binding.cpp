// The Tracker class as Python sees it: keyword settings, OpenCV's init/update pair, and track().
#include <pybind11/pybind11.h>

#include <memory>

#include "py_tracker.hpp"

namespace projtrack::python {

namespace py = pybind11;

namespace {

constexpr const char* kClassDoc =
    "A tracker of one object in a sequence of numpy frames (gray (H, W) or BGR (H, W, 3) "
    "uint8).\n\n"
    "Settings (keywords only): method (projtrack.methods()), model ('appearance': the object's\n"
    "silhouette from its colours and edges; 'flow': the whole object carried along the\n"
    "picture's motion and cut from its surroundings; 'edges': the paper's tracker on edges "
    "alone),\n"
    "acquisition ('manual': wait for init() or a point; 'center'; 'auto': the moving object),\n"
    "the estimators' rays, recursion, block_size, grid_size, max_iterations, convergence,\n"
    "seed_radius and max_gap, the edges' edge_low, edge_high and blur, smoothing (of the pose),\n"
    "max_work (the work a frame may do, × its pixels; 0 unlimited) and fps (the frames' time when\n"
    "track() is given none). A bad setting raises ValueError; a wrong type TypeError.";

std::unique_ptr<PyTracker> make(const std::string& method, const std::string& model,
                                const std::string& acquisition, int rays, int recursion,
                                int block_size, int grid_size, int max_iterations,
                                double convergence, int seed_radius, int max_gap, double edge_low,
                                double edge_high, int blur, bool smoothing, double max_work,
                                double fps) {
  Options o;
  o.method = method;
  o.model = model;
  o.acquisition = acquisition;
  o.params = {rays,           recursion,   block_size,  grid_size,
              max_iterations, convergence, seed_radius, max_gap};
  o.edges.low = edge_low;
  o.edges.high = edge_high;
  o.edges.blur = blur;
  o.smoothing = smoothing;
  o.max_work = max_work;
  o.fps = fps;
  return std::make_unique<PyTracker>(make_settings(o));
}

py::dict settings_dict(const PyTracker& t) {
  const Settings& s = t.settings();
  const Params& p = s.params;
  py::dict d;
  d["method"] = std::string(method_name(s.method));
  d["model"] = model_name(s.tracker.model);
  d["acquisition"] = acquisition_name(s.tracker.acquisition);
  d["rays"] = p.rays, d["recursion"] = p.recursion, d["block_size"] = p.block_size;
  d["grid_size"] = p.grid_size, d["max_iterations"] = p.max_iterations;
  d["convergence"] = p.convergence, d["seed_radius"] = p.seed_radius, d["max_gap"] = p.max_gap;
  d["edge_low"] = s.edges.low, d["edge_high"] = s.edges.high, d["blur"] = s.edges.blur;
  d["smoothing"] = s.tracker.smoothing, d["max_work"] = s.tracker.max_work, d["fps"] = s.fps;
  return d;
}

}  // namespace

void bind_tracker(py::module_& m) {
  const Options o;
  const Params& p = o.params;
  py::class_<PyTracker>(m, "Tracker", kClassDoc)
      .def(py::init(&make), py::kw_only(), py::arg("method") = o.method, py::arg("model") = o.model,
           py::arg("acquisition") = o.acquisition, py::arg("rays") = p.rays,
           py::arg("recursion") = p.recursion, py::arg("block_size") = p.block_size,
           py::arg("grid_size") = p.grid_size, py::arg("max_iterations") = p.max_iterations,
           py::arg("convergence") = p.convergence, py::arg("seed_radius") = p.seed_radius,
           py::arg("max_gap") = p.max_gap, py::arg("edge_low") = o.edges.low,
           py::arg("edge_high") = o.edges.high, py::arg("blur") = o.edges.blur,
           py::arg("smoothing") = o.smoothing, py::arg("max_work") = o.max_work,
           py::arg("fps") = o.fps)
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
            if (!point.is_none() + !box.is_none() + start_mask > 1)
              throw py::value_error("give one of a point, a box or a mask array, not several");
            const Where where{start_mask        ? mask
                              : point.is_none() ? box
                                                : point,
                              start_mask         ? Where::Mask
                              : !point.is_none() ? Where::Point
                              : !box.is_none()   ? Where::Box
                                                 : Where::Nowhere};
            return t.track(frame, where, time, start_mask || mask.cast<bool>());
          },
          py::arg("frame"), py::kw_only(), py::arg("point") = py::none(),
          py::arg("box") = py::none(), py::arg("t") = py::none(), py::arg("mask") = py::bool_(true),
          "The Result of one frame. With `point` (x, y) or `box` (x, y, w, h), a new object\n"
          "from there on this frame. `t`: the frame's time in seconds (default: frames counted\n"
          "at fps). `mask`: whether to draw the silhouette's mask (Result.mask), or an (H, W)\n"
          "array non-zero on the object: a new object from that silhouette on this frame.")
      .def("reset", &PyTracker::reset, "Forgets the object (and restarts the frames' time).")
      .def_property_readonly("settings", &settings_dict, "The tracker's settings, as a dict.")
      .def_property_readonly("frames", &PyTracker::frames, "Frames tracked since the start.")
      .def("__repr__", [](const PyTracker& t) {
        return "<projtrack.Tracker method='" + std::string(method_name(t.settings().method)) +
               "' model='" + model_name(t.settings().tracker.model) + "'>";
      });
}

}  // namespace projtrack::python
