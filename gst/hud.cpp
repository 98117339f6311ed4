#include "hud.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "font.hpp"

namespace projtrack::gst {

namespace {

constexpr Rgb kText{255, 255, 255};
// The status line's colour: green while tracking, red when lost, yellow while searching, white
// when waiting for an inner point, orange when the settings or the frame are wrong.
constexpr Rgb kTracking{64, 255, 64}, kLost{255, 80, 80}, kSearching{255, 230, 0},
    kWaiting{255, 255, 255}, kProblem{255, 160, 0};

Rgb status_colour(TrackStatus s) {
  switch (s) {
    case TrackStatus::Ok:
    case TrackStatus::ReachedBorder:
    case TrackStatus::CoversFrame:
      return kTracking;
    case TrackStatus::Lost:
    case TrackStatus::OverBudget:
      return kLost;
    case TrackStatus::Searching:
      return kSearching;
    case TrackStatus::NoInnerPoint:
      return kWaiting;
    default:
      return kProblem;
  }
}

std::string headline(const TrackResult& r) {
  switch (r.status) {
    case TrackStatus::Ok:
      return "TRACKING";
    case TrackStatus::ReachedBorder:
      return "TRACKING (at the frame border)";
    case TrackStatus::CoversFrame:
      return "TRACKING (covers the frame)";
    case TrackStatus::Lost:
      return "LOST";
    case TrackStatus::Searching:
      return "SEARCHING";
    case TrackStatus::NoInnerPoint:
      return "WAITING";
    case TrackStatus::InvalidParameters:
      return "INVALID SETTINGS";
    default: {
      std::string name(status_name(r.status));
      for (char& c : name) c = c == '-' ? ' ' : static_cast<char>(std::toupper(c));
      return name;
    }
  }
}

std::string format(const char* fmt, double a, double b, double c) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, fmt, a, b, c);
  return buffer;
}

// `line` cut at spaces into lines of at most `columns` characters (a longer word is cut).
void wrap(const std::string& line, std::size_t columns, std::vector<std::string>& out) {
  std::size_t start = 0;
  while (line.size() - start > columns) {
    std::size_t cut = line.rfind(' ', start + columns);
    if (cut == std::string::npos || cut <= start) cut = start + columns;
    out.push_back(line.substr(start, cut - start));
    start = line[cut] == ' ' ? cut + 1 : cut;
  }
  out.push_back(line.substr(start));
}

// The largest n such that a panel of n lines at `scale` is at most a quarter of `height` tall
// (at least 1).
int line_budget(int height, int scale) {
  const int line_height = (kGlyphHeight + 1) * scale, pad = 2 * scale;
  return std::max(1, (height / 4 - 2 * pad + scale) / line_height);
}

bool is_gesture(const std::string& line) {
  return line == "PUSH" || line == "PRESS" || line == "RELEASE";
}

// Which of the lines after the status (`text`'s indexes 1...) a panel keeps, in the order a
// person needs them: a gesture, the pointer, the centroid, the method; each takes its wrapped
// lines while they fit in `budget` with one line of the status. Returns the lines they take.
int keep_lines(const std::vector<std::string>& text,
               const std::vector<std::vector<std::string>>& wrapped, int budget,
               std::vector<bool>& kept) {
  std::vector<std::size_t> order;
  for (std::size_t i = 1; i < text.size(); ++i)
    if (is_gesture(text[i])) order.push_back(i);
  for (std::size_t i = 1; i < text.size(); ++i)
    if (!is_gesture(text[i])) order.push_back(i);
  int used = 0;
  kept.assign(text.size(), false);
  for (std::size_t i : order) {
    const int n = static_cast<int>(wrapped[i].size());
    if (1 + used + n <= budget) {
      kept[i] = true;
      used += n;
    }
  }
  return used;
}

}  // namespace

std::vector<std::string> overlay_text(const TrackResult& r, Method method) {
  const std::string& detail = r.detail.empty() ? r.features.detail : r.detail;
  std::vector<std::string> lines{headline(r) + (detail.empty() ? "" : ": " + detail)};
  if (r.has_pose)
    lines.push_back(format("x %+.2f  y %+.2f  depth %.2f", r.pose.x, r.pose.y, r.pose.depth));
  if (r.features.valid()) {
    const char* what = has_features(r.status) ? "centroid" : "last seen at";
    lines.push_back(std::string(what) + format(" %.0f, %.0f  area %.0f px", r.features.centroid.x,
                                               r.features.centroid.y, r.features.area));
  }
  if (r.gesture != Gesture::None) {  // PUSH, PRESS, RELEASE
    std::string g(gesture_name(r.gesture));
    for (char& c : g) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    lines.push_back(g);
  }
  lines.push_back(std::string("method ") + method_info(method).nick);
  return lines;
}

int text_scale(int frame_height) { return std::clamp(frame_height / 240, 1, 8); }

PanelText panel_lines(const TrackResult& r, Method method, int width, int height) {
  const int scale = text_scale(height);
  const int advance = (kGlyphWidth + 1) * scale, pad = 2 * scale;
  const auto columns = static_cast<std::size_t>(std::max(1, (width - 2 * pad) / advance));
  const std::vector<std::string> text = overlay_text(r, method);
  std::vector<std::vector<std::string>> wrapped(text.size());
  for (std::size_t i = 0; i < text.size(); ++i)
    wrap(drawable(text[i]), columns, wrapped[i]);  // the font's characters: widths count right
  const int budget = line_budget(height, scale);
  std::vector<bool> kept;
  const int others = keep_lines(text, wrapped, budget, kept);
  PanelText panel;
  panel.lines = wrapped[0];
  const auto room = static_cast<std::size_t>(budget - others);
  if (panel.lines.size() > room) {  // cut, and said to be
    panel.lines.resize(room);
    std::string& last = panel.lines.back();
    last = last.substr(0, columns > 3 ? std::min(last.size(), columns - 3) : 0) + "...";
    last.resize(std::min(last.size(), columns));
  }
  panel.status_lines = panel.lines.size();
  for (std::size_t i = 1; i < text.size(); ++i)
    if (kept[i]) panel.lines.insert(panel.lines.end(), wrapped[i].begin(), wrapped[i].end());
  return panel;
}

void draw_panel(Painter& paint, Method method, const TrackResult& result) {
  const int scale = text_scale(paint.height());
  const int advance = (kGlyphWidth + 1) * scale, line_height = (kGlyphHeight + 1) * scale;
  const int pad = 2 * scale;
  const PanelText text = panel_lines(result, method, paint.width(), paint.height());
  std::size_t longest = 0;
  for (const std::string& l : text.lines) longest = std::max(longest, l.size());
  const Rect panel{0, 0, 2 * pad + static_cast<int>(longest) * advance - scale,
                   2 * pad + static_cast<int>(text.lines.size()) * line_height - scale};
  paint.fill(panel, [&](int x, int y) { paint.darken(x, y); });
  const Rgb headline_colour = status_colour(result.status);
  for (std::size_t i = 0; i < text.lines.size(); ++i)
    paint.text(pad, pad + static_cast<int>(i) * line_height, scale, text.lines[i],
               i < text.status_lines ? headline_colour : kText);
}

}  // namespace projtrack::gst
