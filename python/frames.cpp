#include "frames.hpp"

#include <string>

#include "projtrack/color_conversion.hpp"

namespace projtrack::python {

namespace py = pybind11;

namespace {

// The array's shape as a frame: (height, width, channels); throws on what is no frame.
struct Shape {
  int height = 0, width = 0, channels = 1;
};

Shape frame_shape(const py::array& a) {
  const std::string got = "got an array of shape (" + [&] {
    std::string dims;
    for (py::ssize_t i = 0; i < a.ndim(); ++i) dims += (i ? ", " : "") + std::to_string(a.shape(i));
    return dims;
  }() + ")";
  if (a.ndim() != 2 && a.ndim() != 3)
    throw py::value_error("frame: gray (H, W) or BGR (H, W, 3) expected, " + got);
  const py::ssize_t channels = a.ndim() == 3 ? a.shape(2) : 1;
  if (channels != 1 && channels != 3 && channels != 4)
    throw py::value_error("frame: 1, 3 (BGR) or 4 (BGRA) channels expected, " + got);
  if (a.shape(0) < 1 || a.shape(1) < 1) throw py::value_error("frame: it is empty, " + got);
  if (a.shape(0) > kMaxSide || a.shape(1) > kMaxSide)
    throw py::value_error("frame: at most " + std::to_string(kMaxSide) + " px a side, " + got);
  return {static_cast<int>(a.shape(0)), static_cast<int>(a.shape(1)), static_cast<int>(channels)};
}

// Whether the library can read `a` where it is: rows at rising addresses at least a row apart,
// pixels `channels` bytes apart, a pixel's bytes adjacent.
bool readable_in_place(const py::array& a, const Shape& s) {
  if (a.strides(1) != s.channels) return false;
  if (a.ndim() == 3 && s.channels > 1 && a.strides(2) != 1) return false;
  return s.height == 1 || a.strides(0) >= static_cast<py::ssize_t>(s.width) * s.channels;
}

}  // namespace

ColorView FrameReader::read(const py::handle& obj) {
  if (!py::isinstance<py::array>(obj))
    throw py::type_error("frame: a numpy array of uint8 expected, not " +
                         std::string(py::str(obj.get_type().attr("__name__"))));
  py::array a = py::reinterpret_borrow<py::array>(obj);
  if (!a.dtype().is(py::dtype::of<std::uint8_t>()))
    throw py::type_error("frame: dtype uint8 expected, not " + std::string(py::str(a.dtype())) +
                         " (convert with frame.astype(numpy.uint8))");
  const Shape s = frame_shape(a);
  if (!readable_in_place(a, s)) {  // a view of another layout: read a C-ordered copy
    a = py::array::ensure(a, py::array::c_style);
    if (!a) throw py::error_already_set();
  }
  held_ = a;
  channels_ = s.channels;
  const auto* data = static_cast<const std::uint8_t*>(a.data());
  const std::ptrdiff_t stride = s.height == 1 ? s.width * s.channels : a.strides(0);
  ColorView c;
  if (s.channels == 1) {
    // Gray as OpenCV gives it, full range: mapped to video range, as the element's GRAY8.
    c.luma = ImageView(data, s.width, s.height, stride);
    return full_to_video_range(c, planes_);
  }
  // BGR: the library's packed-RGB conversion (video range), as the element's for BGR and BGRx.
  return packed_rgb_to_color(data + 2, data + 1, data, s.channels, stride, s.width, s.height,
                             planes_);
}

}  // namespace projtrack::python
