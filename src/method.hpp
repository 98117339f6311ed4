// The estimators by name: the paper's six and ours, from the table of methods (method_table.def).
#pragma once

#include <cstddef>
#include <iterator>
#include <memory>
#include <optional>
#include <string_view>

namespace projtrack {

class Estimator;

enum class Method {
#define PROJTRACK_METHOD(id, ...) id,
#include "method_table.def"
#undef PROJTRACK_METHOD
};

// Whether an estimate depends on rays (and so on the inner point) or fills a region.
enum class Family { Rays, Fill };

// What an estimator records in a Trace, besides its iterations and the inner-point update's rays.
enum class TraceKind {
  Rays,           // the rays of every iteration and their hits
  RaysAndBlocks,  // those, and the m×m blocks the rays selected
  FilledPixels,   // runs of filled pixels
  GridLines,      // runs along the grid lines that were reached
};

// The factory of one method, defined in its estimator's file.
template <Method>
std::unique_ptr<Estimator> make_estimator();
#define PROJTRACK_METHOD(id, ...) \
  template <>                     \
  std::unique_ptr<Estimator> make_estimator<Method::id>();
#include "method_table.def"
#undef PROJTRACK_METHOD

// One row of the table of methods.
struct MethodInfo {
  Method method;
  // The short name used everywhere outside the code: GStreamer enum nicks, CSV columns, docs. A
  // string literal, so usable as a C string.
  const char* nick;
  const char* description;  // one line, for gst-inspect-1.0 and the docs
  Family family;
  bool iterative;   // max_iterations and convergence apply
  bool from_paper;  // one of the paper's six (else ours, beyond the paper)
  TraceKind trace;
  std::unique_ptr<Estimator> (*make)();
};

// Every method, in the order of its Method value: kMethods[static_cast<int>(m)].method == m.
inline constexpr MethodInfo kMethods[] = {
// clang-format off
#define PROJTRACK_METHOD(id, nick, family, iterative, from_paper, trace, description)     \
  {Method::id, nick, description, Family::family, iterative, from_paper, TraceKind::trace, \
   &make_estimator<Method::id>},
// clang-format on
#include "method_table.def"
#undef PROJTRACK_METHOD
};

inline constexpr int kMethodCount = static_cast<int>(std::size(kMethods));
inline constexpr Method kAllMethods[] = {
#define PROJTRACK_METHOD(id, ...) Method::id,
#include "method_table.def"
#undef PROJTRACK_METHOD
};

// False for an integer cast to Method that is no Method value.
inline bool is_method(Method m) {
  return static_cast<int>(m) >= 0 && static_cast<int>(m) < kMethodCount;
}
// The row of `m`, which must be a Method value.
inline const MethodInfo& method_info(Method m) { return kMethods[static_cast<int>(m)]; }

// The method's nick; "unknown" for an integer that is no Method value. The view is of a string
// literal, so data() is null-terminated (usable as a C string).
std::string_view method_name(Method m);
std::optional<Method> method_from_name(std::string_view name);
// True for the methods whose result depends on rays (and so on the inner point).
bool is_ray_method(Method m);

}  // namespace projtrack
