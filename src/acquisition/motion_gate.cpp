#include "acquisition/motion_gate.hpp"

#include <cstdio>

namespace projtrack {

std::string wait_for_motion(MotionDetector& detector, const ImageView& gray,
                            const MotionDetector::Params& p, double min_motion,
                            MotionDetector::Motion& moved) {
  if (!detector.update(gray, p, moved)) return "waiting for a second frame to compare";
  if (moved.fraction >= min_motion) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "waiting for motion (%.2g %% of the frame changed)",
                100 * moved.fraction);
  return buf;
}

}  // namespace projtrack
