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

// The parameters (params.hpp) a method reads besides `rays` and `seed_radius`, which every method
// reads (the inner-point update casts the rays; the seed is looked for within the radius), and
// max_iterations and convergence, which every iterative method reads: a set of these bits (the
// table's `reads` column).
enum ReadsParam : unsigned {
  kReadsNoOther = 0,
  kReadsRecursion = 1u << 0,  // recursion: y, the levels of re-casting from hit points
  kReadsBlockSize = 1u << 1,  // block_size: m of m-rasterization
  kReadsGridSize = 1u << 2,   // grid_size: m of m-grid-filling
  // max_gap: the longest contour gap a fill will not cross. Such a method reads the edges up to
  // max_gap + 2 px beside what it fills, beyond the box it reports: the edges model widens the
  // region it computes edges in by as much (edge_region.hpp).
  kReadsMaxGap = 1u << 3,
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
  unsigned reads;  // ReadsParam bits: the parameters it reads besides rays (and the iterative ones)
  std::unique_ptr<Estimator> (*make)();
};

// Every method, in the order of its Method value: kMethods[static_cast<int>(m)].method == m.
inline constexpr MethodInfo kMethods[] = {
// clang-format off
#define PROJTRACK_METHOD(id, nick, family, iterative, from_paper, trace, reads, description) \
  {Method::id, nick, description, Family::family, iterative, from_paper, TraceKind::trace,     \
   reads, &make_estimator<Method::id>},
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
