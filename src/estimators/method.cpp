#include "projtrack/method.hpp"

namespace projtrack {

std::string_view method_name(Method m) { return is_method(m) ? method_info(m).nick : "unknown"; }

std::optional<Method> method_from_name(std::string_view name) {
  for (const MethodInfo& info : kMethods) {
    if (info.nick == name) return info.method;
  }
  return std::nullopt;
}

bool is_ray_method(Method m) { return is_method(m) && method_info(m).family == Family::Rays; }

}  // namespace projtrack
