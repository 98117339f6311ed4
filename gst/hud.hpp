// The overlay's text panel: what the tracker says about a frame (the status and why, x, y and
// depth, the centroid, the method), in lines that fit the frame: as wide as it, at most a quarter
// of its height, at a size that grows with it.
#pragma once

#include <string>
#include <vector>

#include "painter.hpp"
#include "projtrack/method.hpp"
#include "projtrack/tracker.hpp"

namespace projtrack::gst {

// The panel's text for one frame: the status in capitals and why (lost, searching, waiting,
// invalid settings...), then x, y and depth and the centroid when there are any, PUSH on a push,
// and the method. Unwrapped.
std::vector<std::string> overlay_text(const TrackResult& r, Method method);

// The text's scale: glyphs of 5×7 pixels (and two rows for descenders) times this: 1 up to 479
// rows, 2 at 640×480, 4 at 1080p.
int text_scale(int frame_height);

// overlay_text() as drawn on a width × height frame: wrapped to its width in the font's
// characters, at most as many lines as fill a quarter of its height (at least one). The status
// keeps its first line; then a push, the pointer, the centroid and the method keep theirs while
// they fit, and the status the lines left (its last one ending in "..." when cut).
struct PanelText {
  std::vector<std::string> lines;
  std::size_t status_lines = 0;  // the first lines: the status and why
};
PanelText panel_lines(const TrackResult& r, Method method, int width, int height);

// The panel at the top left, on a darkened background, its status lines coloured by the status.
void draw_panel(Painter& paint, Method method, const TrackResult& result);

}  // namespace projtrack::gst
