// The inner point or box a user gives, and what the streaming thread does with it before its next
// frame, are written here only.
#include "seeds.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "element.hpp"

namespace projtrack::gst {

namespace {

std::string box_text(const Rect& b) {
  return "<" + std::to_string(b.x) + ", " + std::to_string(b.y) + ", " + std::to_string(b.width) +
         ", " + std::to_string(b.height) + ">";
}

// Why `box` (from `what`) cannot be tracked, or nothing. Sizes are checked one by one: no
// arithmetic on a user's numbers can overflow.
std::string malformed(const char* what, const Rect& box) {
  if (box.width > 0 && box.height > 0) return {};
  return std::string(what) + " " + box_text(box) +
         " refused: its width and height must be at least 1 (<> stops the track, as the reset "
         "signal does)";
}

// start-box: x, y, width, height; or nothing (an empty array). Anything else is refused with why.
std::optional<Rect> box_of(const GValue* array, std::string& why) {
  const guint n = gst_value_array_get_size(array);
  if (n == 0) return Rect{};
  int v[4] = {};
  for (guint i = 0; i < n && i < 4; ++i) {
    const GValue* item = gst_value_array_get_value(array, i);
    if (!G_VALUE_HOLDS_INT(item)) {
      why = "start-box refused: its values must be integers, <x, y, width, height>";
      return std::nullopt;
    }
    v[i] = g_value_get_int(item);
  }
  if (n != 4) {
    why = "start-box refused: it has " + std::to_string(n) +
          " numbers, not the 4 of <x, y, width, height>";
    return std::nullopt;
  }
  const Rect box{v[0], v[1], v[2], v[3]};
  why = malformed("start-box", box);
  if (!why.empty()) return std::nullopt;
  return box;
}

void set_box_value(GValue* array, const Rect& box) {
  if (box.empty()) return;
  for (int v : {box.x, box.y, box.width, box.height}) {
    GValue item = G_VALUE_INIT;
    g_value_init(&item, G_TYPE_INT);
    g_value_set_int(&item, v);
    gst_value_array_append_and_take_value(array, &item);
  }
}

// A malformed seed is refused: the track in hand goes on, and the streaming thread says why.
void refuse_seed_locked(GstProjtrack* self, std::string why) {
  GST_WARNING_OBJECT(self, "%s", why.c_str());
  self->state->locked.seed_note = std::move(why);
}

}  // namespace

void set_inner_point_locked(GstProjtrack* self, int x, int y, bool awaiting_coordinate) {
  ElementSettings& s = self->state->locked.settings;
  s.inner_point_x = x;
  s.inner_point_y = y;
  s.start_box = {};
  if (x >= 0 && y >= 0)
    self->state->locked.pending = SeedCommand::Seed;
  else if (!awaiting_coordinate)
    self->state->locked.pending = SeedCommand::Reset;
}

void set_box_locked(GstProjtrack* self, const Rect& box) {
  ElementSettings& s = self->state->locked.settings;
  s.inner_point_x = s.inner_point_y = -1;
  s.start_box = box.empty() ? Rect{} : box;
  self->state->locked.pending = box.empty() ? SeedCommand::Reset : SeedCommand::SeedBox;
}

void reseed_locked(GstProjtrack* self) {
  if (!self->state->locked.settings.start_box.empty())
    set_box_locked(self, self->state->locked.settings.start_box);
  else
    set_inner_point_locked(self, self->state->locked.settings.inner_point_x,
                           self->state->locked.settings.inner_point_y);
}

// By name, not by GParamSpec: the property table (properties.cpp) calls this file's handlers, and
// this file does not call back into it. A seed changes rarely; the look-up by name costs nothing.
void notify_inner_point(GstProjtrack* self) {
  for (const char* name : {"inner-point-x", "inner-point-y", "start-box"})
    g_object_notify(G_OBJECT(self), name);
}

// Each coordinate is applied as it is set: a new point seeds once both are >= 0.
void set_inner_point_x(GstProjtrack* self, const GValue* value) {
  const int x = g_value_get_int(value);
  set_inner_point_locked(self, x, self->state->locked.settings.inner_point_y, x >= 0);
}

void get_inner_point_x(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->state->locked.settings.inner_point_x);
}

void set_inner_point_y(GstProjtrack* self, const GValue* value) {
  const int y = g_value_get_int(value);
  set_inner_point_locked(self, self->state->locked.settings.inner_point_x, y, y >= 0);
}

void get_inner_point_y(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->state->locked.settings.inner_point_y);
}

void set_start_box(GstProjtrack* self, const GValue* value) {
  std::string why;
  if (const std::optional<Rect> box = box_of(value, why))
    set_box_locked(self, *box);
  else
    refuse_seed_locked(self, std::move(why));
}

void get_start_box(GstProjtrack* self, GValue* value) {
  set_box_value(value, self->state->locked.settings.start_box);
}

void get_current_inner_point_x(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->state->locked.tracked_x);
}

void get_current_inner_point_y(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->state->locked.tracked_y);
}

void track_point(GstProjtrack* self, gint x, gint y) {
  GST_OBJECT_LOCK(self);
  set_inner_point_locked(self, x, y);  // a negative coordinate stops the track
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "track-point %d, %d", x, y);
  notify_inner_point(self);
}

void track_box(GstProjtrack* self, gint x, gint y, gint width, gint height) {
  const Rect box{x, y, width, height};
  std::string why = malformed("track-box", box);
  const bool refused = !why.empty();
  GST_OBJECT_LOCK(self);
  if (refused)
    refuse_seed_locked(self, std::move(why));
  else
    set_box_locked(self, box);
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "track-box %d, %d, %dx%d%s", x, y, width, height,
                  refused ? ": refused" : "");
  if (!refused) notify_inner_point(self);
}

std::string apply_seed(Tracker& tracker, SeedCommand command, const ElementSettings& s, int width,
                       int height) {
  if (command == SeedCommand::Seed) {
    tracker.seed({s.inner_point_x, s.inner_point_y});
  } else if (command == SeedCommand::SeedBox) {
    // Clipped to the picture (in 64 bits: no corner overflows); wholly outside it, not applied.
    const Rect clipped = clip_to_frame(s.start_box, width, height);
    if (clipped.empty())
      return "start-box " + box_text(s.start_box) + " lies outside the " + std::to_string(width) +
             "x" + std::to_string(height) + " picture: not applied";
    tracker.seed_box(clipped);
  } else if (command == SeedCommand::Reset) {
    tracker.reset();
  }
  return {};
}

Point2i rescaled_point(Point2i p, int width, int height, int new_width, int new_height) {
  const auto scale = [](int v, double f) {
    return static_cast<int>(std::clamp(std::floor((v + 0.5) * f), 0.0, double(G_MAXINT)));
  };
  return {scale(p.x, static_cast<double>(new_width) / width),
          scale(p.y, static_cast<double>(new_height) / height)};
}

Rect rescaled_box(const Rect& box, int width, int height, int new_width, int new_height) {
  const double sx = static_cast<double>(new_width) / width;
  const double sy = static_cast<double>(new_height) / height;
  // The part of the box in the old picture (the rest was never applied), scaled.
  const Rect b = clip_to_frame(box, width, height);
  if (b.empty()) return box;
  const int x0 = static_cast<int>(std::floor(b.x * sx)),
            y0 = static_cast<int>(std::floor(b.y * sy));
  const int x1 = static_cast<int>(std::ceil((static_cast<double>(b.x) + b.width) * sx));
  const int y1 = static_cast<int>(std::ceil((static_cast<double>(b.y) + b.height) * sy));
  return {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
}

void rescale_seeds_locked(GstProjtrack* self, int width, int height, int new_width,
                          int new_height) {
  ElementSettings& s = self->state->locked.settings;
  if (s.inner_point_x >= 0 && s.inner_point_y >= 0) {
    const Point2i p =
        rescaled_point({s.inner_point_x, s.inner_point_y}, width, height, new_width, new_height);
    s.inner_point_x = p.x;
    s.inner_point_y = p.y;
  }
  s.start_box = rescaled_box(s.start_box, width, height, new_width, new_height);
  // The objects' lists too, for the next restart (a flush, READY and back).
  for (Point2i& p : s.start_points)
    if (p.x >= 0 && p.y >= 0) p = rescaled_point(p, width, height, new_width, new_height);
  for (Rect& b : s.start_boxes) b = rescaled_box(b, width, height, new_width, new_height);
}

void reset(GstProjtrack* self) {
  GST_OBJECT_LOCK(self);
  set_inner_point_locked(self, -1, -1);
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "reset");
  notify_inner_point(self);
}

}  // namespace projtrack::gst
