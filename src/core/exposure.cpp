#include "projtrack/exposure.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

LumaRange luma_range(const std::array<std::uint32_t, 256>& histogram) {
  std::uint64_t n = 0;
  for (std::uint32_t c : histogram) n += c;
  const std::uint64_t tail = n / 50;
  LumaRange r;
  for (std::uint64_t below = 0; r.lo < 255 && below + histogram[r.lo] <= tail; ++r.lo)
    below += histogram[r.lo];
  for (std::uint64_t above = 0; r.hi > 0 && above + histogram[r.hi] <= tail; --r.hi)
    above += histogram[r.hi];
  r.hi = std::max(r.hi, r.lo);
  return r;
}

LumaRange luma_range(const ImageView& luma, int max_samples) {
  std::array<std::uint32_t, 256> histogram{};
  if (!luma.valid()) return {};
  const double pixels = static_cast<double>(luma.width) * luma.height;
  const int step =
      std::max(1, static_cast<int>(std::ceil(std::sqrt(pixels / std::max(1, max_samples)))));
  for (int y = step / 2; y < luma.height; y += step) {
    const std::uint8_t* row = luma.row(y);
    for (int x = step / 2; x < luma.width; x += step) ++histogram[row[x]];
  }
  return luma_range(histogram);
}

Exposure exposure_for(const LumaRange& r, double dim, double normal, double max_gain) {
  Exposure e;
  const int black = std::min(16, r.lo), bright = r.hi - black;
  // Not dim, or nothing brighter to stretch it to (`normal` is never a darkening).
  if (!(dim > 0) || !(normal > bright) || bright <= 0 || bright >= dim) return e;
  e.gain = std::min(normal / bright, std::max(1.0, max_gain));
  e.black = black;
  return e;
}

}  // namespace projtrack
