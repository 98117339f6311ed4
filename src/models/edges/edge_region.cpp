#include "models/edges/edge_region.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

namespace {

// `box` grown by `margin` on every side, clipped to the frame and anchored on the block grid (so
// rasterized ray-casting's blocks line up with the frame's).
Rect grown(const Rect& box, int margin, int block_size, int width, int height) {
  const int bs = std::max(1, block_size);
  Rect r = clip_to_frame(
      {box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin}, width,
      height);
  const int dx = r.x % bs, dy = r.y % bs;
  return {r.x - dx, r.y - dy, r.width + dx, r.height + dy};
}

// The margin around the last box `b`, px: TrackerParams::edge_margin of its larger side, at least
// kLeastEdgeMargin, and the band of a method that reads max_gap.
int margin_around(const Rect& b, Method m, const Params& params, const TrackerParams& tp) {
  const double grown_by = tp.edge_margin * std::max(b.width, b.height);
  int margin = std::max(kLeastEdgeMargin, static_cast<int>(std::min(grown_by, 1e6)));
  // Gap-tolerant filling reads a band of max_gap + 2 px beside its lines, beyond the box.
  if (method_info(m).reads & kReadsMaxGap) margin += params.max_gap + 2;
  return margin;
}

}  // namespace

Rect edge_region(const Rect& last, Point2d velocity, Method m, const Params& params,
                 const TrackerParams& tp, int width, int height) {
  // The last box and where it would be if it kept its last motion, with a margin around both.
  const Rect ahead{last.x + static_cast<int>(std::lround(velocity.x)),
                   last.y + static_cast<int>(std::lround(velocity.y)), last.width, last.height};
  return grown(last | ahead, margin_around(last, m, params, tp), params.block_size, width, height);
}

Features estimate_in_region(EdgeSource& edges, Estimator& est, Method m, Point2i inner,
                            const Rect* last, Point2d velocity, const Params& params,
                            const EstimateOptions& options, const TrackerParams& tp, Trace* trace) {
  const ImageView& frame = edges.frame();
  const Rect whole{0, 0, frame.width, frame.height};
  Rect region = whole;
  int margin = 0;
  if (tp.edge_margin >= 0 && last) {
    margin = margin_around(*last, m, params, tp);
    const Rect r = edge_region(*last, velocity, m, params, tp, frame.width, frame.height);
    if (r.contains(inner)) region = r;
  }
  for (int growths = 0;; ++growths) {
    const ImageView e = edges.region(region);
    Features f = est.estimate(e, {inner.x - region.x, inner.y - region.y}, params, options, trace);
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
    region = growths == 0 ? grown(region | b, margin, params.block_size, frame.width, frame.height)
                          : whole;
  }
}

}  // namespace projtrack
