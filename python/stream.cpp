#include "stream.hpp"

#include <cmath>

#include "seeds.hpp"

namespace projtrack::python {

namespace py = pybind11;

std::unique_lock<std::mutex> FrameStream::lock() {
  std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
  py::gil_scoped_release nogil;
  lock.lock();
  return lock;
}

double FrameStream::seconds(const py::object& t, bool restart) const {
  if (t.is_none()) return static_cast<double>(restart ? 0 : frames_.load()) / fps_;
  const double s = number(t, "t");
  if (!std::isfinite(s)) throw py::value_error("t: a finite number of seconds expected");
  return s;
}

}  // namespace projtrack::python
