// How a start from a box or a click ended.
#pragma once

#include <string>

namespace projtrack {

struct StartOutcome {
  enum class Kind {
    Cut,           // the object was cut out: the mask holds it
    NothingToCut,  // no contrast there to cut (`why`): the mask is empty
    Stopped,       // the frame's budget could not pay for the next stage, or the stop flag was set
  };
  Kind kind = Kind::Cut;
  std::string why;

  static StartOutcome cut() { return {}; }
  static StartOutcome nothing(std::string why) { return {Kind::NothingToCut, std::move(why)}; }
  static StartOutcome stopped() { return {Kind::Stopped, {}}; }
};

}  // namespace projtrack
