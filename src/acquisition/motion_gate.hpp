// The gate of the edges model's automatic acquisition: it looks for a new object only on a
// frame that moved, and says what it waits for otherwise.
#pragma once

#include <string>

#include "acquisition/motion_detector.hpp"
#include "projtrack/image_view.hpp"

namespace projtrack {

// Compares `gray` with `detector`'s last frame into `moved`. Empty when at least `min_motion` of
// the frame changed; else what acquisition waits for (a second frame, or more motion).
std::string wait_for_motion(MotionDetector& detector, const ImageView& gray,
                            const MotionDetector::Params& p, double min_motion,
                            MotionDetector::Motion& moved);

// Whether `moved`'s changed samples are spread evenly over a width × height frame (fresh noise, a
// flash): every cell of an 8 × 8 grid holds some, and none twice as many as the median cell.
bool changed_evenly(const MotionDetector::Motion& moved, int width, int height);

}  // namespace projtrack
