#include "acquisition/separation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace projtrack {

namespace {

constexpr int kBins = 8 * 8 * 8;

int coarse_bin(const ColorView& f, int x, int y) {
  const int luma = f.luma.row(y)[x] >> 5;
  if (!f.has_chroma()) return luma;
  return luma << 6 | (f.chroma.u_at(x, y) >> 5) << 3 | (f.chroma.v_at(x, y) >> 5);
}

}  // namespace

double colour_separation(const ColorView& frame, const Mask& region, MaskOps& ops, Mask& scratch) {
  const double area = moments(region).area;
  if (area <= 0) return 0;
  const int width = std::max(2, static_cast<int>(std::lround(0.25 * std::sqrt(area))));
  const Rect& r = region.rect();
  embed(region, {r.x - width, r.y - width, r.width + 2 * width, r.height + 2 * width}, scratch);
  Mask grown;
  ops.dilate(scratch, width, grown);
  std::array<double, kBins> inside{}, around{};
  double n_in = 0, n_around = 0;
  const Rect& g = grown.rect();
  const Rect frame_rect{0, 0, frame.luma.width, frame.luma.height};
  for (int y = std::max(g.y, 0); y < std::min(g.bottom(), frame_rect.height); ++y)
    for (int x = std::max(g.x, 0); x < std::min(g.right(), frame_rect.width); ++x) {
      if (!grown.at({x, y})) continue;
      const int b = coarse_bin(frame, x, y);
      if (region.at({x, y}))
        inside[b] += 1, n_in += 1;
      else
        around[b] += 1, n_around += 1;
    }
  if (n_in <= 0 || n_around <= 0) return 0;
  double bc = 0;
  for (int b = 0; b < kBins; ++b) bc += std::sqrt(inside[b] / n_in * around[b] / n_around);
  return 1 - bc;
}

}  // namespace projtrack
