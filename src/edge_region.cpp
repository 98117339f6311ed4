#include "edge_region.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

// `box` grown by `margin` on every side, clipped to the frame and anchored on the block grid (so
// rasterized ray-casting's blocks line up with the frame's).
Rect grown(const Rect& box, int margin, int block_size, const ImageView& frame) {
  const int bs = std::max(1, block_size);
  Rect r = clip_to_frame(
      {box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin},
      frame.width, frame.height);
  const int dx = r.x % bs, dy = r.y % bs;
  return {r.x - dx, r.y - dy, r.width + dx, r.height + dy};
}

}  // namespace

Features estimate_in_region(EdgeSource& edges, Estimator& est, Method m, Point2i inner,
                            const Rect* last, Point2d velocity, const Params& params,
                            const TrackerParams& tp, Trace* trace) {
  const ImageView& frame = edges.frame();
  const Rect whole{0, 0, frame.width, frame.height};
  Rect region = whole;
  int margin = 0;
  if (tp.edge_margin >= 0 && last) {
    // The last box and where it would be if it kept its last motion, with a margin around both.
    const Rect& b = *last;
    const Rect ahead{b.x + static_cast<int>(std::lround(velocity.x)),
                     b.y + static_cast<int>(std::lround(velocity.y)), b.width, b.height};
    const double grown_by = tp.edge_margin * std::max(b.width, b.height);
    margin = std::max(16, static_cast<int>(std::min(grown_by, 1e6)));
    // Gap-tolerant filling reads a band of max_gap + 2 px beside its lines, beyond the box.
    if (m == Method::GapTolerantFilling) margin += params.max_gap + 2;
    const Rect r = grown(b | ahead, margin, params.block_size, frame);
    if (r.contains(inner)) region = r;
  }
  for (int growths = 0;; ++growths) {
    const ImageView e = edges.region(region);
    Features f = est.estimate(e, {inner.x - region.x, inner.y - region.y}, params, trace);
    translate(f, region.x, region.y);
    if (trace) trace->translate(region.x, region.y);
    if (!f.valid()) return f;
    // Reaching the region's edge (where it is not the frame's) means the region cut the estimate:
    // redo it on a larger region. (Except through Canny's hysteresis, which is not local: a weak
    // edge joined to a strong one only outside the region is missing inside it. docs/tracker.md
    // says so.) Edges within a few pixels of an inner border may differ from the frame's (later
    // filter passes replicate the region's border), so coming that close counts as cut too.
    const int g = edges.border_guard();
    const Rect& b = f.reach;
    const bool cut = (b.x <= region.x + g && region.x > 0) ||
                     (b.y <= region.y + g && region.y > 0) ||
                     (b.right() >= region.right() - g && region.right() < frame.width) ||
                     (b.bottom() >= region.bottom() - g && region.bottom() < frame.height);
    // A fill stopped at the limit and not cut by the region is refused anyway: no regrowing.
    if (!cut || region == whole) {
      f.status = border_status(f.bbox, frame.width, frame.height);
      return f;
    }
    // First around the cut estimate with four times the margin (a fast or growing object), then
    // the whole frame (a leak, which the tracker must see whole to refuse).
    margin *= 4;
    region = growths == 0 ? grown(region | b, margin, params.block_size, frame) : whole;
  }
}

}  // namespace projtrack
