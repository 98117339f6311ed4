#include "settings.hpp"

#include <pybind11/pybind11.h>

#include <cmath>
#include <optional>

namespace projtrack::python {

namespace py = pybind11;

const char* model_name(ObjectModelKind k) {
  switch (k) {
    case ObjectModelKind::Edges:
      return "edges";
    case ObjectModelKind::Flow:
      return "flow";
    case ObjectModelKind::Appearance:
      break;
  }
  return "appearance";
}

const char* acquisition_name(Acquisition a) {
  switch (a) {
    case Acquisition::Manual:
      return "manual";
    case Acquisition::Center:
      return "center";
    case Acquisition::Auto:
      return "auto";
  }
  return "manual";
}

std::string method_names() {
  std::string names;
  for (const MethodInfo& info : kMethods)
    names += (names.empty() ? "" : ", ") + std::string(info.nick);
  return names;
}

namespace {

template <class Enum, std::size_t N>
std::optional<Enum> by_name(const std::string& name, const Enum (&values)[N],
                            const char* (*name_of)(Enum)) {
  for (Enum v : values)
    if (name == name_of(v)) return v;
  return std::nullopt;
}

[[noreturn]] void bad(const std::string& what) { throw py::value_error(what); }

}  // namespace

Settings make_settings(const Options& o) {
  Settings s;
  const std::optional<Method> method = method_from_name(o.method);
  if (!method) bad("method '" + o.method + "' is none of: " + method_names());
  s.method = *method;
  const std::optional<ObjectModelKind> model =
      by_name(o.model, {ObjectModelKind::Appearance, ObjectModelKind::Edges, ObjectModelKind::Flow},
              model_name);
  if (!model) bad("model '" + o.model + "' is none of: appearance, edges, flow");
  s.tracker.model = *model;
  const std::optional<Acquisition> acquisition =
      by_name(o.acquisition, {Acquisition::Manual, Acquisition::Center, Acquisition::Auto},
              acquisition_name);
  if (!acquisition) bad("acquisition '" + o.acquisition + "' is none of: manual, center, auto");
  s.tracker.acquisition = *acquisition;
  if (std::string why = validate(o.params); !why.empty()) bad(why);
  if (std::string why = validate(o.edges); !why.empty()) bad(why);
  if (!(o.edges.low >= 0) || !(o.edges.high >= 0)) bad("edge_low and edge_high must be at least 0");
  if (o.edges.blur < 0 || o.edges.blur > kMaxBlurPasses)
    bad("blur = " + std::to_string(o.edges.blur) + " is outside [0, " +
        std::to_string(kMaxBlurPasses) + "]");
  if (!(o.max_work >= 0 && o.max_work <= kMaxMaxWork))
    bad("max_work = " + std::to_string(o.max_work) + " is outside [0, " +
        std::to_string(kMaxMaxWork) + "] (0: unlimited)");
  if (!(o.fps > 0 && std::isfinite(o.fps))) bad("fps must be a positive number");
  s.params = o.params;
  s.edges = o.edges;
  s.tracker.smoothing = o.smoothing;
  s.tracker.max_work = o.max_work;
  s.fps = o.fps;
  return s;
}

}  // namespace projtrack::python
