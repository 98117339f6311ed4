#include "py_multi_tracker.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

namespace projtrack::python {

namespace py = pybind11;

namespace {

// `s` into a cleared width × height mask, each work pixel an s×s block of 255 clipped to the
// frame, as Tracker::silhouette() draws a Tracker's: the library draws only those (its drawing
// is private to src/); false when there is no silhouette.
bool draw(const SilhouetteMask& s, std::uint8_t* out, int width, int height) {
  std::memset(out, 0, static_cast<std::size_t>(width) * height);
  if (s.empty()) return false;
  const int x0 = std::max(0, s.rect.x * s.scale), x1 = std::min(width, s.rect.right() * s.scale);
  const int y0 = std::max(0, s.rect.y * s.scale), y1 = std::min(height, s.rect.bottom() * s.scale);
  for (int y = y0; y < y1; ++y) {
    const std::uint8_t* in = s.mask.row(y / s.scale - s.rect.y) - s.rect.x;
    std::uint8_t* row = out + static_cast<std::ptrdiff_t>(y) * width;
    for (int x = x0; x < x1; ++x) row[x] = in[x / s.scale] ? 255 : 0;
  }
  return true;
}

std::string unknown_id(int id, const std::vector<int>& ids) {
  std::string list;
  for (const int i : ids) list += (list.empty() ? "" : ", ") + std::to_string(i);
  return "no object of id " + std::to_string(id) + " (ids: [" + list + "])";
}

}  // namespace

int PyMultiTracker::add(const py::handle& frame, const Where& where) {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  const ColorView view = stream_.read(frame);
  const int w = view.luma.width, h = view.luma.height;
  const Seed s = parse_seed(where, w, h);
  // The objects followed already are checked against the start in this frame's pixels: a frame
  // of a new size rescales them first, as the next frame of that size would.
  stream_.follow(tracker_, w, h);
  Added added;
  if (s.kind == Where::Point) added = tracker_.add_point(s.point, w, h);
  if (s.kind == Where::Box) added = tracker_.add_box(s.box, w, h);
  if (s.kind == Where::Mask) added = tracker_.add_mask(ImageView(s.mask.data(), w, h, w));
  if (!added) throw py::value_error("add: " + added.why);
  return added.id;
}

void PyMultiTracker::remove(int id) {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  if (!tracker_.remove(id)) throw py::value_error("remove: " + unknown_id(id, tracker_.ids()));
}

void PyMultiTracker::clear() {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  tracker_.clear();
}

std::vector<int> PyMultiTracker::ids() {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  return tracker_.ids();
}

std::size_t PyMultiTracker::size() {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  return tracker_.size();
}

py::object PyMultiTracker::mask(int id) {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  if (!tracker_.contains(id)) throw py::value_error("mask: " + unknown_id(id, tracker_.ids()));
  const int w = stream_.width(), h = stream_.height();
  if (w <= 0) return py::none();
  py::array_t<std::uint8_t> mask({h, w});
  if (!draw(tracker_.silhouette(id), mask.mutable_data(), w, h)) return py::none();
  return std::move(mask);
}

std::vector<Result> PyMultiTracker::results(const py::handle& frame, const py::object& t,
                                            bool with_mask) {
  const std::unique_lock<std::mutex> lock = stream_.lock();
  const ColorView view = stream_.read(frame);
  const int w = view.luma.width, h = view.luma.height;
  const double seconds = stream_.seconds(t, false);
  stream_.follow(tracker_, w, h);
  // The masks are made with the GIL and drawn without it, as the frame is tracked.
  std::vector<py::array_t<std::uint8_t>> masks;
  if (with_mask)
    for (std::size_t i = 0; i < tracker_.size(); ++i) masks.emplace_back(std::vector<int>{h, w});
  std::vector<TrackResult> tracked;
  std::vector<bool> drawn(masks.size(), false);
  {
    py::gil_scoped_release nogil;
    tracked = tracker_.track(view, seconds, options_.settings);
    for (std::size_t i = 0; i < masks.size() && i < tracked.size(); ++i)
      drawn[i] = draw(tracker_.silhouette(tracked[i].id), masks[i].mutable_data(), w, h);
    stream_.count();
  }
  std::vector<Result> out(tracked.size());
  for (std::size_t i = 0; i < tracked.size(); ++i) {
    out[i].r = std::move(tracked[i]);
    if (i < drawn.size() && drawn[i]) out[i].mask = std::move(masks[i]);
  }
  return out;
}

py::dict PyMultiTracker::track(const py::handle& frame, const py::object& t, bool with_mask) {
  py::dict d;
  for (Result& r : results(frame, t, with_mask)) {
    const int id = r.r.id;
    d[py::int_(id)] = py::cast(std::move(r));
  }
  return d;
}

py::tuple PyMultiTracker::update(const py::handle& frame) {
  const std::vector<Result> rs = results(frame, py::none(), false);
  py::array_t<double> boxes({static_cast<py::ssize_t>(rs.size()), py::ssize_t{4}});
  auto b = boxes.mutable_unchecked<2>();
  bool ok = true;
  for (std::size_t i = 0; i < rs.size(); ++i) {
    ok = ok && rs[i].ok();
    const Rect r = rs[i].r.features.valid() ? rs[i].r.features.bbox : Rect{};
    const py::ssize_t row = static_cast<py::ssize_t>(i);
    b(row, 0) = r.x;
    b(row, 1) = r.y;
    b(row, 2) = r.width;
    b(row, 3) = r.height;
  }
  return py::make_tuple(ok, boxes);
}

}  // namespace projtrack::python
