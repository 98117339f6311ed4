// Frame differencing's parameters (the tracker's motion gate and the edges model's acquisition).
#pragma once

namespace projtrack {

struct MotionParams {
  int threshold = 25;  // grey levels of change that count as motion
  int step = 2;        // compare every step-th pixel of every step-th row
};

}  // namespace projtrack
