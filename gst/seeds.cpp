// The inner point or box a user gives, and what the streaming thread does with it before its next
// frame, are written here only.
#include "seeds.hpp"

#include "element.hpp"
#include "properties.hpp"

namespace projtrack::gst {

namespace {

// start-box: x, y, width, height, or nothing (an empty array, or width or height under 1).
Rect box_of(const GValue* array) {
  if (gst_value_array_get_size(array) != 4) return {};
  int v[4];
  for (guint i = 0; i < 4; ++i) {
    const GValue* item = gst_value_array_get_value(array, i);
    if (!G_VALUE_HOLDS_INT(item)) return {};
    v[i] = g_value_get_int(item);
  }
  return {v[0], v[1], v[2], v[3]};
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

}  // namespace

void set_inner_point_locked(GstProjtrack* self, int x, int y, bool awaiting_coordinate) {
  Settings& s = *self->settings;
  s.seed_x = x;
  s.seed_y = y;
  s.seed_box = {};
  if (x >= 0 && y >= 0)
    self->pending = SeedCommand::Seed;
  else if (!awaiting_coordinate)
    self->pending = SeedCommand::Reset;
}

void set_box_locked(GstProjtrack* self, const Rect& box) {
  Settings& s = *self->settings;
  s.seed_x = s.seed_y = -1;
  s.seed_box = box.empty() ? Rect{} : box;
  self->pending = box.empty() ? SeedCommand::Reset : SeedCommand::SeedBox;
}

void reseed_locked(GstProjtrack* self) {
  if (!self->settings->seed_box.empty())
    set_box_locked(self, self->settings->seed_box);
  else
    set_inner_point_locked(self, self->settings->seed_x, self->settings->seed_y);
}

void notify_inner_point(GstProjtrack* self) {
  for (PropertyId prop : {PROP_INNER_POINT_X, PROP_INNER_POINT_Y, PROP_START_BOX})
    g_object_notify_by_pspec(G_OBJECT(self), property_spec(prop));
}

// Each coordinate is applied as it is set: a new point seeds once both are >= 0.
void set_inner_point_x(GstProjtrack* self, const GValue* value) {
  const int x = g_value_get_int(value);
  set_inner_point_locked(self, x, self->settings->seed_y, x >= 0);
}

void get_inner_point_x(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->settings->seed_x);
}

void set_inner_point_y(GstProjtrack* self, const GValue* value) {
  const int y = g_value_get_int(value);
  set_inner_point_locked(self, self->settings->seed_x, y, y >= 0);
}

void get_inner_point_y(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->settings->seed_y);
}

void set_start_box(GstProjtrack* self, const GValue* value) { set_box_locked(self, box_of(value)); }

void get_start_box(GstProjtrack* self, GValue* value) {
  set_box_value(value, self->settings->seed_box);
}

void get_current_inner_point_x(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->tracked_x);
}

void get_current_inner_point_y(GstProjtrack* self, GValue* value) {
  g_value_set_int(value, self->tracked_y);
}

void track_point(GstProjtrack* self, gint x, gint y) {
  GST_OBJECT_LOCK(self);
  set_inner_point_locked(self, x, y);  // a negative coordinate stops the track
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "track-point %d, %d", x, y);
  notify_inner_point(self);
}

void track_box(GstProjtrack* self, gint x, gint y, gint width, gint height) {
  GST_OBJECT_LOCK(self);
  set_box_locked(self, {x, y, width, height});  // an empty box stops the track
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "track-box %d, %d, %dx%d", x, y, width, height);
  notify_inner_point(self);
}

void reset(GstProjtrack* self) {
  GST_OBJECT_LOCK(self);
  set_inner_point_locked(self, -1, -1);
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "reset");
  notify_inner_point(self);
}

}  // namespace projtrack::gst
