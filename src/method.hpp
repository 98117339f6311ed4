// The estimators: the paper's six and our gap-tolerant filling, by name.
#pragma once

#include <optional>
#include <string_view>

namespace projtrack {

enum class Method {
  RayCasting,            // n-ray-casting
  IterativeRayCasting,   // iterative n-ray-casting
  RecursiveRayCasting,   // iterative n^y-ray-casting
  RasterizedRayCasting,  // iterative n^y-ray-casting with m-rasterization
  PixelFilling,          // pixel-filling
  GridFilling,           // m-grid-filling (the paper's proposal)
  GapTolerantFilling,    // m-grid-filling whose lines do not squeeze through contour gaps (ours)
};

inline constexpr int kMethodCount = 7;
inline constexpr Method kAllMethods[kMethodCount] = {
    Method::RayCasting,           Method::IterativeRayCasting, Method::RecursiveRayCasting,
    Method::RasterizedRayCasting, Method::PixelFilling,        Method::GridFilling,
    Method::GapTolerantFilling};

// The short name used everywhere outside the code: GStreamer enum nicks, CSV columns, docs. The
// view is of a string literal, so data() is null-terminated (usable as a C string).
std::string_view method_name(Method m);
std::optional<Method> method_from_name(std::string_view name);
// True for the methods whose result depends on rays (and so on the inner point).
bool is_ray_method(Method m);

}  // namespace projtrack
