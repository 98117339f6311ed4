#include "estimators/pixel_filling.hpp"

#include <cmath>

namespace projtrack {

void PixelFilling::run(const Context& ctx, Features& out, Work& work) {
  const ImageView& edges = ctx.edges;
  const int width = edges.width, height = edges.height;
  filled_.ensure(width, height);
  filled_.clear(kept_ & Rect{0, 0, width, height});  // the last fill, paid for by its estimate
  pending_.clear();
  pending_.push_back(out.seed);
  std::uint64_t count = 0, sum_x = 0, sum_y = 0;
  BoundsAccumulator bounds;
  const double limit = ctx.options.area_limit > 0 ? ctx.options.area_limit : HUGE_VAL;

  std::size_t next = 0;
  while (next < pending_.size() && static_cast<double>(count) <= limit && !work.must_stop()) {
    const Point2i s = pending_[next++];
    const std::uint8_t* e = edges.row(s.y);
    std::uint8_t* f = filled_.row(s.y);
    work.fill(1);
    work.cost += kCostPerRun;
    if (e[s.x] || f[s.x]) continue;  // filled since it was queued
    int x0 = s.x, x1 = s.x;
    while (x0 > 0 && !e[x0 - 1] && !f[x0 - 1]) --x0;
    while (x1 < width - 1 && !e[x1 + 1] && !f[x1 + 1]) ++x1;
    const int len = x1 - x0 + 1;
    work.fill(len + 1);
    for (int x = x0; x <= x1; ++x) f[x] = 1;
    count += len;
    sum_x += static_cast<std::uint64_t>(x0 + x1) * len / 2;
    sum_y += static_cast<std::uint64_t>(s.y) * len;
    bounds.add_run(x0, x1, s.y);
    if (ctx.trace) ctx.trace->runs.push_back({{x0, s.y}, {x1, s.y}});
    // Queue the start of every free run next to this one, above and below.
    for (int ny = s.y - 1; ny <= s.y + 1; ny += 2) {
      if (ny < 0 || ny >= height) continue;
      const std::uint8_t* ne = edges.row(ny);
      const std::uint8_t* nf = filled_.row(ny);
      bool in_run = false;
      for (int x = x0; x <= x1; ++x) {
        const bool free = !ne[x] && !nf[x];
        if (free && !in_run) pending_.push_back({x, ny});
        in_run = free;
      }
      work.fill(len);
    }
  }

  out.area = static_cast<double>(count);
  out.centroid = {static_cast<double>(sum_x) / count, static_cast<double>(sum_y) / count};
  out.bbox = bounds.rect();
  out.iterations = 1;
  if (ctx.trace) ctx.trace->iterations.push_back({out.seed, out.centroid, out.area});
  // Kept for took_in() until the next fill clears it; its clearing counted now, so that what an
  // estimate costs does not depend on the one before.
  kept_ = out.bbox;
  work.cost += clearing_cost(out.bbox.width, out.bbox.height);
}

std::uint64_t PixelFilling::add_fill_to(ScratchMask& into, Rect& box) const {
  for (int y = kept_.y; y < kept_.bottom(); ++y) {
    const std::uint8_t* f = filled_.row(y);
    std::uint8_t* o = into.row(y);
    for (int x = kept_.x; x < kept_.right(); ++x) o[x] |= f[x];
  }
  box |= kept_;
  return static_cast<std::uint64_t>(kept_.width) * kept_.height / kScannedPixelsPerCost;
}

template <>
std::unique_ptr<Estimator> make_estimator<Method::PixelFilling>() {
  return std::make_unique<PixelFilling>();
}

}  // namespace projtrack
