#include "projtrack/gesture.hpp"

namespace projtrack {

std::string_view gesture_name(Gesture g) {
  switch (g) {
    case Gesture::Push:
      return "push";
    case Gesture::Press:
      return "press";
    case Gesture::Release:
      return "release";
    case Gesture::None:
      break;
  }
  return {};
}

}  // namespace projtrack
