#include "seeds.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace projtrack::python {

namespace py = pybind11;

Where one_of(std::initializer_list<Where> starts) {
  Where chosen;
  for (const Where& w : starts) {
    if (!w.obj) continue;
    if (chosen.kind != Where::Nowhere)
      throw py::value_error("give one of a point, a box or a mask array, not several");
    chosen = w;
  }
  return chosen;
}

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

namespace {

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

// `a`'s shape as numpy prints it: (), (4,), (240, 320, 3).
std::string shape_text(const py::array& a) {
  std::string dims;
  for (py::ssize_t i = 0; i < a.ndim(); ++i) dims += (i ? ", " : "") + std::to_string(a.shape(i));
  return "(" + dims + (a.ndim() == 1 ? ",)" : ")");
}

// One element of a mask: the background (zero), the object (any other number) or NaN, which is
// neither and is refused rather than guessed.
enum class Pixel { Off, On, NaN };

// numpy's float16, which C++17 has no type for: read by its IEEE half-precision bits.
struct Half {
  std::uint16_t bits;
};

// The element at `p` as a T: memcpy, as numpy does not promise aligned data, with its bytes
// reversed first when the array is of the other byte order.
template <typename T>
Pixel pixel_at(const char* p, bool swapped) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (swapped) std::reverse(bytes, bytes + sizeof(T));
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  if constexpr (std::is_same_v<T, Half>) {
    if ((v.bits & 0x7C00) == 0x7C00 && (v.bits & 0x03FF) != 0) return Pixel::NaN;
    return (v.bits & 0x7FFF) != 0 ? Pixel::On : Pixel::Off;  // -0 is zero
  } else {
    if constexpr (std::is_floating_point_v<T>)
      if (std::isnan(v)) return Pixel::NaN;
    return v != 0 ? Pixel::On : Pixel::Off;
  }
}

// The first NaN of a mask (its column x and row y) and how many it holds.
struct NaNs {
  long count = 0;
  py::ssize_t x = 0, y = 0;
};

// The 2-D array `a` of T, any strides, as 255 where it is non-zero and 0 elsewhere into `out`.
template <typename T>
NaNs binarize(const py::array& a, bool swapped, std::uint8_t* out) {
  const auto* data = static_cast<const char*>(a.data());
  NaNs nans;
  for (py::ssize_t y = 0; y < a.shape(0); ++y) {
    const char* row = data + y * a.strides(0);
    for (py::ssize_t x = 0; x < a.shape(1); ++x) {
      const Pixel p = pixel_at<T>(row + x * a.strides(1), swapped);
      if (p == Pixel::NaN && nans.count++ == 0) {
        nans.x = x;
        nans.y = y;
      }
      *out++ = p == Pixel::On ? 255 : 0;
    }
  }
  return nans;
}

using Binarizer = NaNs (*)(const py::array&, bool swapped, std::uint8_t* out);

// The reader of a mask of dtype `dt` in that dtype (a cast to uint8 first would make 0.5, 256 or
// inf zero): bool, signed and unsigned ints of 1 to 8 bytes, float16, float32 and float64; a
// TypeError for another, naming `what` the mask is.
Binarizer binarizer_for(const py::dtype& dt, const std::string& what) {
  const char kind = dt.kind();
  const py::ssize_t size = dt.itemsize();
  if (kind == 'b' || kind == 'i' || kind == 'u') {  // zero or not: the sign does not matter
    if (size == 1) return binarize<std::uint8_t>;
    if (size == 2) return binarize<std::uint16_t>;
    if (size == 4) return binarize<std::uint32_t>;
    if (size == 8) return binarize<std::uint64_t>;
  }
  if (kind == 'f') {
    if (size == 2) return binarize<Half>;
    if (size == 4) return binarize<float>;
    if (size == 8) return binarize<double>;
  }
  throw py::type_error(
      "mask: a numeric dtype expected (bool, int8-64, uint8-64, float16/32/64), not " + what);
}

// The mask `obj` as the object's silhouette on a width × height frame, non-zero on the object: a
// TypeError for what holds no numbers, a ValueError for another shape, a NaN or no pixel set.
std::vector<std::uint8_t> parse_mask(const py::handle& obj, int width, int height) {
  const bool given_array = py::isinstance<py::array>(obj);
  const py::array a = py::array::ensure(obj);  // an array as it is, a nested list converted
  const std::string type_name = py::str(obj.get_type().attr("__name__"));
  if (!a) throw py::type_error("mask: a numeric (H, W) array expected, not " + type_name);
  const std::string dtype_name = py::str(a.dtype());
  const Binarizer binarize = binarizer_for(
      a.dtype(), given_array ? dtype_name : type_name + " (as an array: " + dtype_name + ")");
  if (a.ndim() != 2 || a.shape(0) != height || a.shape(1) != width)
    throw py::value_error(
        "mask: an (H, W) = (" + std::to_string(height) + ", " + std::to_string(width) +
        ") array expected, non-zero on the object, not one of shape " + shape_text(a));
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * height);
  const NaNs nans = binarize(a, !a.dtype().attr("isnative").cast<bool>(), mask.data());
  if (nans.count > 0)
    throw py::value_error("mask: holds NaN at (x, y) = (" + std::to_string(nans.x) + ", " +
                          std::to_string(nans.y) + ") (" + std::to_string(nans.count) +
                          " NaNs in all): a NaN is neither zero nor the object; replace them "
                          "first (numpy.nan_to_num(mask) makes them 0)");
  if (std::none_of(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; }))
    throw py::value_error("mask: no pixel is set (non-zero): there is no object in it");
  return mask;
}

// How a seed of `kind` is written, for the errors.
const char* written_as(Where::Kind kind) {
  return kind == Where::Point ? "(x, y)"
         : kind == Where::Box ? "(x, y, width, height)"
                              : "(x, y) or (x, y, width, height)";
}

}  // namespace

// The seed `where` gives in a width × height frame: a ValueError for a point outside it, a box
// without area or outside it, a mask of another shape, empty or holding NaN, another count of
// numbers, or an array of another dimension; a TypeError for what are not numbers. A box is
// clipped to the frame.
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
  // An array neither a mask nor one row of numbers (0-d, 3-d; 2-d as a point or box): said here,
  // where reading its numbers would raise an IndexError or a TypeError about its rows.
  if (py::isinstance<py::array>(where.obj)) {
    const auto a = py::reinterpret_borrow<py::array>(where.obj);
    if (a.ndim() != 1)
      throw py::value_error((where.kind == Where::Either
                                 ? std::string("where: a point (x, y), a box (x, y, w, h) or an "
                                               "(H, W) mask")
                                 : std::string(what) + ": " + written_as(where.kind)) +
                            " expected, not an array of shape " + shape_text(a));
  }
  const std::vector<double> v = numbers(where.obj, what);
  const bool point = v.size() == 2 && where.kind != Where::Box;
  const bool box = v.size() == 4 && where.kind != Where::Point;
  if (!point && !box)
    throw py::value_error(std::string(what) + ": " + written_as(where.kind) + " expected, not " +
                          std::to_string(v.size()) + " numbers");
  s.kind = point ? Where::Point : Where::Box;
  if (point) s.point = parse_point(v, width, height);
  if (box) s.box = parse_box(v, width, height);
  return s;
}

}  // namespace projtrack::python
