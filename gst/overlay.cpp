#include "overlay.hpp"

#include <cmath>

#include "hud.hpp"
#include "painter.hpp"

namespace projtrack::gst {

namespace {

constexpr Rgb kOutline{0, 255, 0}, kFill{0, 255, 255}, kGrid{255, 0, 255}, kBlock{64, 128, 255},
    kRay{0, 255, 0}, kHit{255, 255, 0}, kBox{255, 0, 0}, kHeldBox{255, 160, 0},
    kCentroid{255, 0, 0}, kInnerPoint{255, 255, 0};

// What the method did, as the paper's figures show it: filled pixels tinted, grid lines, selected
// blocks, the last iteration's rays and their hits.
void draw_trace(Painter& paint, Method method, const Trace& trace) {
  const bool grid = method_info(method).trace == TraceKind::GridLines;
  for (const Trace::Run& run : trace.runs) {
    for (int y = run.first.y; y <= run.last.y; ++y)
      for (int x = run.first.x; x <= run.last.x; ++x) {
        if (grid)
          paint.set(x, y, kGrid);
        else
          paint.tint(x, y, kFill);
      }
  }
  for (const Trace::Block& b : trace.blocks) {
    paint.fill(b.rect, [&](int x, int y) { paint.tint(x, y, kBlock); });
    paint.outline(b.rect, kBlock);
  }
  // The rays of the last iteration (the inner-point updates' rays, iteration 0, are left out).
  const int last = trace.last_recorded_iteration();
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == last && last > 0) paint.line(r.origin, r.hit, kRay);
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == last && last > 0) paint.square(round_to_pixel(r.hit), 1, kHit);
}

}  // namespace

void draw_overlay(GstVideoFrame* frame, Method method, const TrackResult& result,
                  const Trace& trace, unsigned flags) {
  Painter paint(frame);
  const Features& features = result.features;
  if (flags & kDrawGrid) draw_trace(paint, method, trace);
  // The silhouette the estimator ran on (the flow model's), as thick as the text's strokes.
  const int scale = text_scale(paint.height());
  if (flags & kDrawOutline)
    for (const Point2i& p : trace.outline)
      paint.fill({p.x, p.y, scale, scale}, [&](int x, int y) { paint.set(x, y, kOutline); });
  const bool tracking = has_features(result.status);
  if (features.valid() && (flags & kDrawBox))
    paint.outline(features.bbox, tracking ? kBox : kHeldBox);
  if (tracking && (flags & kDrawCentroid)) paint.cross(features.centroid, 3 * scale + 3, kCentroid);
  if (tracking && (flags & kDrawInnerPoint)) paint.square(features.inner_point, scale, kInnerPoint);
  if (flags & kDrawStatus) draw_panel(paint, method, result);
}

}  // namespace projtrack::gst
