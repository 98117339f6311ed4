#include "objects_overlay.hpp"

#include <algorithm>
#include <string>

#include "hud.hpp"
#include "painter.hpp"

namespace projtrack::gst {

namespace {

// Colours far from one another and from the single track's red and green, by id: an object
// keeps its colour while it is followed.
constexpr Rgb kPalette[] = {{0, 160, 255},  {255, 0, 255},   {255, 200, 0},   {0, 255, 200},
                            {255, 120, 60}, {160, 100, 255}, {255, 255, 255}, {120, 200, 0}};

Rgb colour_of(int id) {
  constexpr int n = sizeof(kPalette) / sizeof(kPalette[0]);
  return kPalette[(id - 1 + n) % n];
}

void draw_outline(Painter& paint, const std::vector<std::vector<Point2i>>& outline, Rgb c) {
  for (const std::vector<Point2i>& polygon : outline)
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Point2i a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      paint.line({double(a.x), double(a.y)}, {double(b.x), double(b.y)}, c);
    }
}

// The id, and the status when the object is not tracked on this frame, above its box (inside
// it when the box touches the top), on a darkened background so that it reads on any picture.
void draw_label(Painter& paint, const TrackResult& r, int scale, Rgb c) {
  std::string label = std::to_string(r.id);
  if (!has_features(r.status)) label += " " + std::string(status_name(r.status));
  const Rect& b = r.features.bbox;
  const int h = kGlyphHeight * scale + 2;
  const int w = static_cast<int>(label.size()) * (kGlyphWidth + 1) * scale + 2;
  const int top = b.y - h >= 0 ? b.y - h : b.y;
  paint.fill({b.x, top, w, h}, [&](int x, int y) { paint.darken(x, y); });
  paint.text(b.x + 1, top + 1, scale, label, c);
}

}  // namespace

void draw_objects(GstVideoFrame* frame, const ObjectsFrame& objects, unsigned flags) {
  Painter paint(frame);
  const int scale = text_scale(paint.height());
  for (std::size_t i = 0; i < objects.results.size(); ++i) {
    const TrackResult& r = objects.results[i];
    const Rgb c = colour_of(r.id);
    if (flags & kDrawOutline) draw_outline(paint, objects.outlines[i], c);
    if (!r.features.valid()) continue;  // nothing measured yet: no place to draw it
    if (flags & kDrawBox) paint.outline(r.features.bbox, c);
    if (has_features(r.status) && (flags & kDrawCentroid))
      paint.cross(r.features.centroid, 3 * scale + 3, c);
    draw_label(paint, r, scale, c);
  }
}

}  // namespace projtrack::gst
