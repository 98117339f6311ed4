#include "settings.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <utility>

#include "projtrack/color_view.hpp"
#include "projtrack/names.hpp"

namespace projtrack::python {

namespace py = pybind11;

Settings python_defaults() {
  Settings s;
  s.tracker.acquisition = Acquisition::Manual;
  // FrameReader gives the tracker every frame at video range: an edge map's black is 16 there.
  s.edges.input_black_level = kVideoBlack;
  return s;
}

TrackerOptions multi_defaults() {
  TrackerOptions o{python_defaults()};
  o.max_objects = 8;
  return o;
}

namespace {

// The keywords' names before they were the element's: still taken, never given back.
constexpr std::pair<std::string_view, std::string_view> kFormerNames[] = {
    {"model", "object_model"},
    {"edge_low", "edge_threshold_low"},
    {"edge_high", "edge_threshold_high"},
};

std::string type_name(const py::handle& v) {
  return std::string(py::str(v.get_type().attr("__name__")));
}

// The message for an int `v` that the member's type cannot hold (beyond C's int, or a double's
// range): the setting's range as validate() words it, from `probe` (validate() of the defaults with
// the member at `extreme`, the nearest value of its type), with the number given.
template <class T, class Probe>
std::string beyond_type(const py::handle& v, const std::string& key, T extreme,
                        const Probe& probe) {
  const std::string given = key + " = " + std::string(py::repr(v));
  const std::string why = probe(extreme);
  const std::string head = key + " = ";  // "key = value <why>": the value is the one given
  const std::size_t rest = why.find(' ', head.size());
  if (why.rfind(head, 0) == 0 && rest != std::string::npos) return given + why.substr(rest);
  if (!why.empty()) return given + " is out of range: " + why;
  return given + (std::is_integral_v<T> ? " is beyond C's int" : " is beyond a double's range");
}

// `v` into `member`, as the member's type takes it: an enum from one of its nicks, a number or a
// bool as pybind11 converts an argument of that type. An int the type cannot hold is out of the
// setting's range (a ValueError, as any other), not of the wrong type.
template <class T, class Probe>
void read(const py::handle& v, const std::string& key, T& member, const Probe& probe) {
  if constexpr (std::is_enum_v<T>) {
    if (!py::isinstance<py::str>(v))
      throw py::type_error(key + ": a name (str) expected, not " + type_name(v));
    const std::string nick = v.cast<std::string>();
    const std::optional<T> value = from_nick<T>(nick);
    if (!value) throw py::value_error(key + " '" + nick + "' is none of: " + nick_list<T>());
    member = *value;
  } else {
    py::detail::make_caster<T> caster;
    if (!caster.load(v, true)) {
      if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
        if (PyLong_Check(v.ptr()) && !PyBool_Check(v.ptr())) {
          PyErr_Clear();
          const bool negative = py::int_(py::reinterpret_borrow<py::object>(v)) < py::int_(0);
          throw py::value_error(beyond_type(
              v, key, negative ? std::numeric_limits<T>::lowest() : std::numeric_limits<T>::max(),
              probe));
        }
      }
      throw py::type_error(key + ": " + (std::is_same_v<T, bool> ? "a bool" : "a number") +
                           " expected, not " + type_name(v) + " " + std::string(py::repr(v)));
    }
    member = py::detail::cast_op<T>(caster);
  }
}

// `member` as Python shows it: an enum by its nick.
template <class T>
py::object shown(const T& member) {
  if constexpr (std::is_enum_v<T>)
    return py::str(nick_of(member));
  else
    return py::cast(member);
}

// Sets the setting named `key` (a keyword of the table) from `v`; false when there is none.
bool set_setting(Settings& s, const std::string& key, const py::handle& v) {
  // What validate() says of the defaults with this one member at `extreme`.
#define PROJTRACK_KEYWORD(name, member)       \
  if (key == name) {                          \
    read(v, key, s.member, [](auto extreme) { \
      Settings probe = python_defaults();     \
      probe.member = extreme;                 \
      return validate(probe);                 \
    });                                       \
    return true;                              \
  }
#include "keyword_table.def"
#undef PROJTRACK_KEYWORD
  return false;
}

}  // namespace

TrackerOptions options_from(const py::kwargs& kwargs, const TrackerOptions& defaults,
                            const char* cls) {
  TrackerOptions o = defaults;
  const auto too_few = [](int n) {
    return n >= 1 ? std::string() : "max_objects = " + std::to_string(n) + " is not at least 1";
  };
  std::set<std::string> given;
  for (const auto& [k, v] : kwargs) {
    std::string key = py::cast<std::string>(k);
    for (const auto& [former, now] : kFormerNames)
      if (key == former) key = now;
    if (!given.insert(key).second) throw py::type_error(key + " given twice");
    if (key == "fps")
      read(v, key, o.fps, [](double fps) {
        return fps > 0 ? std::string() : "fps = " + std::to_string(fps) + " is not positive";
      });
    else if (key == "max_objects" && defaults.max_objects > 0)
      read(v, key, o.max_objects, too_few);
    else if (!set_setting(o.settings, key, v))
      throw py::type_error(std::string(cls) + "() got an unexpected keyword argument '" +
                           py::cast<std::string>(k) + "'");
  }
  if (std::string why = validate(o.settings); !why.empty()) throw py::value_error(why);
  if (!(o.fps > 0 && std::isfinite(o.fps))) throw py::value_error("fps must be a positive number");
  if (std::string why = too_few(o.max_objects); defaults.max_objects > 0 && !why.empty())
    throw py::value_error(why);
  return o;
}

py::dict options_dict(const TrackerOptions& o) {
  py::dict d;
  const Settings& s = o.settings;
#define PROJTRACK_KEYWORD(name, member) d[name] = shown(s.member);
#include "keyword_table.def"
#undef PROJTRACK_KEYWORD
  d["fps"] = o.fps;
  if (o.max_objects > 0) d["max_objects"] = o.max_objects;
  return d;
}

std::string keywords_doc(const TrackerOptions& defaults) {
  std::ostringstream doc;
  for (const auto& [key, value] : options_dict(defaults))
    doc << "    " << std::string(py::str(key)) << "=" << std::string(py::repr(value)) << "\n";
  return doc.str();
}

}  // namespace projtrack::python
