#include "acquisition/seed_region.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace projtrack {

namespace {

constexpr int kLevels = 256;
// How far apart two tolerances are compared for stability (MSER's Δ), in distance levels.
constexpr int kStabilityStep = 8;

struct Colour {
  int y = 0, u = 128, v = 128;
};

Colour colour_at(const ColorView& f, int x, int y) {
  if (!f.has_chroma()) return {f.luma.row(y)[x], 128, 128};
  return {f.luma.row(y)[x], f.chroma.u_at(x, y), f.chroma.v_at(x, y)};
}

// Chroma weighs twice luma: the shades of one surface differ in brightness far more than in hue.
int colour_distance(const Colour& a, const Colour& b) {
  const int d = std::max({std::abs(a.y - b.y), 2 * std::abs(a.u - b.u), 2 * std::abs(a.v - b.v)});
  return std::min(d, kLevels - 1);
}

int median9(std::array<int, 9> v) {
  std::nth_element(v.begin(), v.begin() + 4, v.end());
  return v[4];
}

}  // namespace

void SeedRegion::distances(const ColorView& f, Point2i seed) {
  const int w = f.luma.width, h = f.luma.height;
  std::array<int, 9> ys{}, us{}, vs{};
  int k = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx, ++k) {
      const Colour c =
          colour_at(f, std::clamp(seed.x + dx, 0, w - 1), std::clamp(seed.y + dy, 0, h - 1));
      ys[k] = c.y, us[k] = c.u, vs[k] = c.v;
    }
  const Colour ref{median9(ys), median9(us), median9(vs)};
  const int stride = w + 2;  // a border of one pixel: see bottlenecks()
  distance_.assign(static_cast<std::size_t>(stride) * (h + 2), kLevels - 1);
  for (int y = 0; y < h; ++y) {
    std::uint8_t* d = distance_.data() + static_cast<std::size_t>(y + 1) * stride + 1;
    for (int x = 0; x < w; ++x)
      d[x] = static_cast<std::uint8_t>(colour_distance(colour_at(f, x, y), ref));
  }
}

void SeedRegion::bottlenecks(int w, int h, Point2i seed) {
  // On the frame with a border of one pixel that is never reached (its bottleneck 0 is no
  // larger than any level): a pixel's four neighbours need no bounds check.
  const int stride = w + 2;
  bottleneck_.assign(static_cast<std::size_t>(stride) * (h + 2), 0);
  for (int y = 0; y < h; ++y)
    std::fill_n(bottleneck_.begin() + static_cast<std::ptrdiff_t>(y + 1) * stride + 1, w,
                kLevels);  // kLevels: not reached yet
  buckets_.resize(kLevels);
  for (auto& b : buckets_) b.clear();
  const std::int32_t s = (seed.y + 1) * stride + seed.x + 1;
  bottleneck_[s] = distance_[s];
  buckets_[distance_[s]].push_back(s);
  const std::int32_t near[4] = {-1, 1, -stride, stride};
  for (int level = 0; level < kLevels; ++level) {
    auto& bucket = buckets_[level];
    while (!bucket.empty()) {  // the bucket may grow while it is emptied (the same level)
      const std::int32_t p = bucket.back();
      bucket.pop_back();
      if (bottleneck_[p] != level) continue;  // taken at a lower level already
      for (const std::int32_t d : near) {
        const std::int32_t q = p + d;
        const int b = std::max<int>(level, distance_[q]);
        if (b < bottleneck_[q]) {
          bottleneck_[q] = static_cast<std::uint16_t>(b);
          buckets_[b].push_back(q);
        }
      }
    }
  }
}

int SeedRegion::most_stable(int w, int h, double least, double most) const {
  std::array<std::int64_t, kLevels + 1> area{};
  std::array<std::uint8_t, kLevels + 1> sides{};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int b = bottleneck_[static_cast<std::size_t>(y + 1) * (w + 2) + x + 1];
      ++area[b];
      sides[b] |= (x == 0) | (x == w - 1) << 1 | (y == 0) << 2 | (y == h - 1) << 3;
    }
  for (int t = 1; t <= kLevels; ++t) {
    area[t] += area[t - 1];
    sides[t] |= sides[t - 1];
  }
  int best = -1;
  double best_change = 0;
  for (int t = kStabilityStep; t + kStabilityStep < kLevels; ++t) {
    const double a = static_cast<double>(area[t]);
    if (a < least || a > most || sides[t] == 0xF) continue;
    const double change = (area[t + kStabilityStep] - area[t - kStabilityStep]) / a;
    if (best < 0 || change < best_change) best = t, best_change = change;
  }
  return best;
}

bool SeedRegion::grow(const ColorView& frame, Point2i origin, Point2i seed, double least,
                      double most, Mask& out, MaskOps& ops) {
  const int w = frame.luma.width, h = frame.luma.height;
  const Point2i s{seed.x - origin.x, seed.y - origin.y};
  if (w <= 0 || h <= 0 || s.x < 0 || s.y < 0 || s.x >= w || s.y >= h) return false;
  distances(frame, s);
  bottlenecks(w, h, s);
  const int t = most_stable(w, h, least, most);
  if (t < 0) return false;
  out.reset({origin.x, origin.y, w, h});
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = out.row(y);
    const std::uint16_t* b = bottleneck_.data() + static_cast<std::size_t>(y + 1) * (w + 2) + 1;
    for (int x = 0; x < w; ++x) o[x] = b[x] <= t;
  }
  ops.fill_holes(out);
  out.crop();
  return !out.empty();
}

}  // namespace projtrack
