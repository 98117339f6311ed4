// The names of the enums a user chooses from (the element's enum properties, Python's string
// keywords): one table per enum, made from its .def file (method_table.def,
// edge_detector_table.def, acquisition_table.def, object_model_table.def), and the look-ups both
// ways. The element's GEnums and the Python module read these tables, so a new value is one row.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "edge_detection.hpp"
#include "method.hpp"
#include "tracker_params.hpp"

namespace projtrack {

// One value of an enum and its names.
template <class E>
struct NameRow {
  E value;
  const char* nick;         // the name outside the code: enum nick, Python string, docs
  const char* description;  // one line, for gst-inspect-1.0 and the docs
};

inline constexpr NameRow<Method> kMethodNames[] = {
#define PROJTRACK_METHOD(id, nick, family, iterative, from_paper, trace, reads, description) \
  {Method::id, nick, description},
#include "method_table.def"
#undef PROJTRACK_METHOD
};
inline constexpr NameRow<EdgeDetector> kEdgeDetectorNames[] = {
#define PROJTRACK_NAME(value, nick, description) {EdgeDetector::value, nick, description},
#include "edge_detector_table.def"
#undef PROJTRACK_NAME
};
inline constexpr NameRow<Acquisition> kAcquisitionNames[] = {
#define PROJTRACK_NAME(value, nick, description) {Acquisition::value, nick, description},
#include "acquisition_table.def"
#undef PROJTRACK_NAME
};
inline constexpr NameRow<ObjectModelKind> kObjectModelNames[] = {
#define PROJTRACK_OBJECT_MODEL(id, value, nick, description) \
  {ObjectModelKind::id, nick, description},
#include "object_model_table.def"
#undef PROJTRACK_OBJECT_MODEL
};

// The table of E: names_of<E>() is an array of NameRow<E>.
template <class E>
constexpr const auto& names_of();
template <>
constexpr const auto& names_of<Method>() {
  return kMethodNames;
}
template <>
constexpr const auto& names_of<EdgeDetector>() {
  return kEdgeDetectorNames;
}
template <>
constexpr const auto& names_of<Acquisition>() {
  return kAcquisitionNames;
}
template <>
constexpr const auto& names_of<ObjectModelKind>() {
  return kObjectModelNames;
}

// The nick of `v`; "unknown" for an integer that is no value of E.
template <class E>
const char* nick_of(E v) {
  for (const NameRow<E>& row : names_of<E>())
    if (row.value == v) return row.nick;
  return "unknown";
}

// The value named `nick`, if any.
template <class E>
std::optional<E> from_nick(std::string_view nick) {
  for (const NameRow<E>& row : names_of<E>())
    if (nick == row.nick) return row.value;
  return std::nullopt;
}

// Every nick of E in the table's order, as "a, b, c" (for messages and the docs).
template <class E>
std::string nick_list() {
  std::string list;
  for (const NameRow<E>& row : names_of<E>())
    list += (list.empty() ? "" : ", ") + std::string(row.nick);
  return list;
}

}  // namespace projtrack
