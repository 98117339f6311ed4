#include "status.hpp"

namespace projtrack {

std::string_view status_name(Status s) {
  switch (s) {
    case Status::Ok:
      return "ok";
    case Status::ReachedBorder:
      return "reached-border";
    case Status::CoversFrame:
      return "covers-frame";
    case Status::Lost:
      return "lost";
    case Status::Searching:
      return "searching";
    case Status::NoInnerPoint:
      return "no-inner-point";
    case Status::InnerPointOutside:
      return "inner-point-outside";
    case Status::InnerPointOnEdge:
      return "inner-point-on-edge";
    case Status::EmptyImage:
      return "empty-image";
    case Status::InvalidImage:
      return "invalid-image";
    case Status::InvalidParameters:
      return "invalid-parameters";
  }
  return "unknown";
}

}  // namespace projtrack
