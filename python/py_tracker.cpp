#include "py_tracker.hpp"

#include <pybind11/numpy.h>

#include <cstdint>
#include <utility>

namespace projtrack::python {

namespace py = pybind11;

namespace {

void apply(Tracker& tracker, const Seed& s, int width, int height) {
  if (s.kind == Where::Point) tracker.seed(s.point);
  if (s.kind == Where::Box) tracker.seed_box(s.box);
  if (s.kind == Where::Mask) tracker.seed_mask(ImageView(s.mask.data(), width, height, width));
}

}  // namespace

Result PyTracker::track(const py::handle& frame, const Where& where, const py::object& t,
                        bool with_mask) {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  const ColorView view = stream_.read(frame);
  const int w = view.luma.width, h = view.luma.height;
  const double seconds = stream_.seconds(t, where.restart);
  const Seed start = parse_seed(where, w, h);  // first: a bad one leaves the track as it was
  stream_.follow(tracker_, w, h);
  apply(tracker_, start, w, h);
  if (where.restart) stream_.restart();
  Result res;
  py::array_t<std::uint8_t> mask;
  if (with_mask) mask = py::array_t<std::uint8_t>({h, w});
  bool has_mask = false;
  {
    py::gil_scoped_release nogil;
    res.r = tracker_.track(view, seconds, options_.settings);
    if (with_mask) has_mask = tracker_.silhouette(mask.mutable_data(), w, h, w);
    stream_.count();
  }
  if (has_mask) res.mask = std::move(mask);
  return res;
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
  const std::unique_lock<std::mutex> lock = stream_.lock();
  tracker_.reset();
  stream_.restart();
}

}  // namespace projtrack::python
