#include "core/work_scale.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

int floor_div(long long a, int b) { return static_cast<int>(a >= 0 ? a / b : -((-a + b - 1) / b)); }

}  // namespace

int work_scale(double pixels, double target) {
  if (!(pixels > 0) || !(target > 0)) return 1;
  return std::max(1, static_cast<int>(std::lround(std::sqrt(pixels / target))));
}

Rect to_work(const Rect& r, int scale) {
  const int s = std::max(1, scale);
  const int x0 = floor_div(r.x, s), y0 = floor_div(r.y, s);
  const int x1 = floor_div(static_cast<long long>(r.x) + r.width + s - 1, s);
  const int y1 = floor_div(static_cast<long long>(r.y) + r.height + s - 1, s);
  return {x0, y0, x1 - x0, y1 - y0};
}

Rect to_frame(const Rect& r, int scale, int width, int height) {
  const long long s = std::max(1, scale);
  const auto clamp_int = [](long long v) {
    return static_cast<int>(std::clamp<long long>(v, -(1LL << 30), 1LL << 30));
  };
  return clip_to_frame(
      {clamp_int(r.x * s), clamp_int(r.y * s), clamp_int(r.width * s), clamp_int(r.height * s)},
      width, height);
}

}  // namespace projtrack
