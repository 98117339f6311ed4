#include "py_tracker.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace projtrack::python {

namespace py = pybind11;

namespace {

// `obj` as a number: a TypeError naming `what` for anything else.
double number(const py::handle& obj, const std::string& what) {
  const double d = PyFloat_AsDouble(obj.ptr());
  if (d == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::type_error(what + ": a number expected, not " +
                         std::string(py::str(obj.get_type().attr("__name__"))));
  }
  return d;
}

// The numbers of `where`: a TypeError for what is no sequence of numbers, a ValueError for a
// number that is not finite or lies far beyond any frame.
std::vector<double> numbers(const py::handle& where, const std::string& what) {
  if (!py::isinstance<py::sequence>(where) || py::isinstance<py::str>(where))
    throw py::type_error(what + ": a sequence of numbers expected, not " +
                         std::string(py::str(where.get_type().attr("__name__"))));
  std::vector<double> v;
  for (const py::handle item : py::reinterpret_borrow<py::sequence>(where)) {
    const double d = number(item, what);
    if (!(std::abs(d) <= 1e9))
      throw py::value_error(what + ": " + std::string(py::repr(item)) + " is no pixel coordinate");
    v.push_back(d);
  }
  return v;
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

Point2i parse_point(const std::vector<double>& v, int width, int height) {
  const Point2i p{static_cast<int>(std::lround(v[0])), static_cast<int>(std::lround(v[1]))};
  if (p.x < 0 || p.y < 0 || p.x >= width || p.y >= height)
    throw py::value_error("point: (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                          ") lies outside the " + size_text(width, height) + " frame");
  return p;
}

Rect parse_box(const std::vector<double>& v, int width, int height) {
  if (!(v[2] >= 1 && v[3] >= 1))
    throw py::value_error("box: its width and height must be at least 1 px, not " +
                          std::to_string(v[2]) + " and " + std::to_string(v[3]));
  const Rect r{static_cast<int>(std::lround(v[0])), static_cast<int>(std::lround(v[1])),
               static_cast<int>(std::lround(v[2])), static_cast<int>(std::lround(v[3]))};
  const Rect in = clip_to_frame(r, width, height);  // a box partly outside: its part inside
  if (in.empty())
    throw py::value_error("box: (" + std::to_string(r.x) + ", " + std::to_string(r.y) + ", " +
                          std::to_string(r.width) + ", " + std::to_string(r.height) +
                          ") lies outside the " + size_text(width, height) + " frame");
  return in;
}

bool is_mask(const Where& where) {
  if (where.kind == Where::Mask) return true;
  return where.kind == Where::Either && py::isinstance<py::array>(where.obj) &&
         py::reinterpret_borrow<py::array>(where.obj).ndim() == 2;
}

// A seed read and checked, not yet given to the tracker: a bad one raises before the tracker
// changes (a new size rescales it first, and the seed is in the new frame's pixels).
struct Seed {
  Where::Kind kind = Where::Nowhere;  // Nowhere, Point, Box or Mask
  Point2i point;
  Rect box;
  py::array_t<std::uint8_t> mask;
};

// The mask `obj` as the object's silhouette on a width × height frame: a ValueError for another
// shape or a mask with no pixel set. Any numeric dtype; non-zero is the object.
py::array_t<std::uint8_t> parse_mask(const py::handle& obj, int width, int height) {
  auto m = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(
      py::reinterpret_borrow<py::object>(obj));
  if (!m || m.ndim() != 2 || m.shape(0) != height || m.shape(1) != width)
    throw py::value_error("mask: an (H, W) = (" + std::to_string(height) + ", " +
                          std::to_string(width) + ") array expected, non-zero on the object");
  const std::uint8_t* d = m.data();
  if (std::none_of(d, d + m.size(), [](std::uint8_t v) { return v != 0; }))
    throw py::value_error("mask: no pixel is set (non-zero): there is no object in it");
  return m;
}

// The seed `where` gives in a width × height frame: a ValueError for a point outside it, a box
// without area or outside it, a mask of another shape or empty, or another count of numbers; a
// TypeError for what are not numbers. A box is clipped to the frame.
Seed parse_seed(const Where& where, int width, int height) {
  Seed s;
  if (where.kind == Where::Nowhere) return s;
  if (is_mask(where)) {
    s.kind = Where::Mask;
    s.mask = parse_mask(where.obj, width, height);
    return s;
  }
  const char* what = where.kind == Where::Point ? "point"
                     : where.kind == Where::Box ? "box"
                                                : "point or box";
  const std::vector<double> v = numbers(where.obj, what);
  const bool point = v.size() == 2 && where.kind != Where::Box;
  const bool box = v.size() == 4 && where.kind != Where::Point;
  if (!point && !box)
    throw py::value_error(std::string(what) + ": " +
                          (where.kind == Where::Point ? "(x, y)"
                           : where.kind == Where::Box ? "(x, y, width, height)"
                                                      : "(x, y) or (x, y, width, height)") +
                          " expected, not " + std::to_string(v.size()) + " numbers");
  s.kind = point ? Where::Point : Where::Box;
  if (point) s.point = parse_point(v, width, height);
  if (box) s.box = parse_box(v, width, height);
  return s;
}

void apply(Tracker& tracker, const Seed& s, int width, int height) {
  if (s.kind == Where::Point) tracker.seed(s.point);
  if (s.kind == Where::Box) tracker.seed_box(s.box);
  if (s.kind == Where::Mask) tracker.seed_mask(ImageView(s.mask.data(), width, height, width));
}

}  // namespace

Result PyTracker::track(const py::handle& frame, const Where& where, const py::object& t,
                        bool with_mask) {
  std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
  {  // waits for another thread's frame without the GIL, which that thread needs to finish
    py::gil_scoped_release nogil;
    lock.lock();
  }
  const ColorView view = reader_.read(frame);
  const int w = view.luma.width, h = view.luma.height;
  double seconds = static_cast<double>(where.restart ? 0 : frames_.load()) / options_.fps;
  if (!t.is_none()) {
    seconds = number(t, "t");
    if (!std::isfinite(seconds)) throw py::value_error("t: a finite number of seconds expected");
  }
  const Seed start = parse_seed(where, w, h);  // first: a bad one leaves the track as it was
  reframe(w, h, reader_.channels());
  apply(tracker_, start, w, h);
  if (where.restart) frames_ = 0;
  Result res;
  py::array_t<std::uint8_t> mask;
  if (with_mask) mask = py::array_t<std::uint8_t>({h, w});
  bool has_mask = false;
  {
    py::gil_scoped_release nogil;
    res.r = tracker_.track(view, seconds, options_.settings);
    if (with_mask) has_mask = tracker_.silhouette(mask.mutable_data(), w, h, w);
    ++frames_;
  }
  if (has_mask) res.mask = std::move(mask);
  return res;
}

void PyTracker::reframe(int width, int height, int channels) {
  // As the element takes new caps (gst/stream.cpp, set_info()): another size rescales the track,
  // another kind of frame at the same size (gray, BGR, BGRA: another format) relearns its colours.
  if (width_ > 0 && (width != width_ || height != height_))
    tracker_.rescale(width_, height_, width, height);
  else if (channels_ > 0 && channels != channels_)
    tracker_.relearn();
  width_ = width;
  height_ = height;
  channels_ = channels;
}

bool PyTracker::init(const py::handle& frame, const py::handle& where) {
  return track(frame, {where, Where::Either, true}, py::none(), false).ok();
}

py::tuple PyTracker::update(const py::handle& frame) {
  const Result r = track(frame, {}, py::none(), false);
  const Rect b = r.ok() ? r.r.features.bbox : Rect{};
  return py::make_tuple(r.ok(), py::make_tuple(b.x, b.y, b.width, b.height));
}

void PyTracker::reset() {
  std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
  {
    py::gil_scoped_release nogil;
    lock.lock();
  }
  tracker_.reset();
  frames_ = 0;
}

}  // namespace projtrack::python
