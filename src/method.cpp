#include "method.hpp"

namespace projtrack {

std::string_view method_name(Method m) {
  switch (m) {
    case Method::RayCasting:
      return "ray-casting";
    case Method::IterativeRayCasting:
      return "iterative-ray-casting";
    case Method::RecursiveRayCasting:
      return "recursive-ray-casting";
    case Method::RasterizedRayCasting:
      return "rasterized-ray-casting";
    case Method::PixelFilling:
      return "pixel-filling";
    case Method::GridFilling:
      return "grid-filling";
    case Method::GapTolerantFilling:
      return "gap-tolerant-filling";
  }
  return "unknown";
}

std::optional<Method> method_from_name(std::string_view name) {
  for (Method m : kAllMethods) {
    if (method_name(m) == name) return m;
  }
  return std::nullopt;
}

bool is_ray_method(Method m) {
  return m != Method::PixelFilling && m != Method::GridFilling && m != Method::GapTolerantFilling;
}

}  // namespace projtrack
