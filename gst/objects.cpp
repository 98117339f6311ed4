// The objects a user starts beside the single track, and the checks their starts pass, are
// written here only.
#include "objects.hpp"

#include <array>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "element.hpp"

namespace projtrack::gst {

namespace {

using Tuple = std::array<int, 4>;

std::string serialized(const GValue* v) {
  gchar* text = gst_value_serialize(v);
  std::string out = text ? text : "?";
  g_free(text);
  return out;
}

// An entry as a user wrote it, <1, 2, 3> (gst_value_serialize() would add each item's type).
std::string entry_text(const GValue* entry) {
  if (!GST_VALUE_HOLDS_ARRAY(entry)) return serialized(entry);
  std::string out = "<";
  for (guint k = 0; k < gst_value_array_get_size(entry); ++k)
    out += (k ? ", " : "") + serialized(gst_value_array_get_value(entry, k));
  return out + ">";
}

// Why entry `i` of `what` is not a tuple of `arity` ints (`shape` names them), or nothing.
std::string malformed_entry(const GValue* entry, guint i, guint arity, const char* what,
                            const char* shape, Tuple& out) {
  const std::string named =
      std::string(what) + " refused: entry " + std::to_string(i + 1) + " " + entry_text(entry);
  if (!GST_VALUE_HOLDS_ARRAY(entry)) return named + " is not a tuple " + shape;
  const guint n = gst_value_array_get_size(entry);
  if (n != arity)
    return named + " has " + std::to_string(n) + " numbers, not the " + std::to_string(arity) +
           " of " + shape;
  for (guint k = 0; k < n; ++k) {
    const GValue* item = gst_value_array_get_value(entry, k);
    if (!G_VALUE_HOLDS_INT(item)) return named + " holds a value that is not an integer";
    out[k] = g_value_get_int(item);
  }
  return {};
}

// The tuples of a start-boxes or start-points value; nothing (and why, naming the first malformed
// entry) when one is malformed: the list is taken whole or not at all.
std::optional<std::vector<Tuple>> tuples_of(const GValue* value, guint arity, const char* what,
                                            const char* shape, std::string& why) {
  std::vector<Tuple> tuples;
  for (guint i = 0; i < gst_value_array_get_size(value); ++i) {
    Tuple t{};
    why = malformed_entry(gst_value_array_get_value(value, i), i, arity, what, shape, t);
    if (!why.empty()) return std::nullopt;
    tuples.push_back(t);
  }
  return tuples;
}

void append_tuple(GValue* array, std::initializer_list<int> numbers) {
  GValue tuple = G_VALUE_INIT;
  gst_value_array_init(&tuple, numbers.size());
  for (int v : numbers) {
    GValue item = G_VALUE_INIT;
    g_value_init(&item, G_TYPE_INT);
    g_value_set_int(&item, v);
    gst_value_array_append_and_take_value(&tuple, &item);
  }
  gst_value_array_append_and_take_value(array, &tuple);
}

// A malformed list is refused: the objects in hand go on, and the streaming thread warns.
void refuse_list_locked(GstProjtrack* self, const std::string& why) {
  GST_WARNING_OBJECT(self, "%s", why.c_str());
  std::string& note = self->state->locked.objects_note;
  note += (note.empty() ? "" : "; ") + why;
}

// Why no object may be added to `objects` now that `max_objects` are allowed, or nothing.
std::string over_limit(const Objects& objects, int max_objects) {
  const std::size_t n = objects.tracker.size();
  if (n < static_cast<std::size_t>(max_objects)) return {};
  return "already following " + std::to_string(n) + " objects, max-objects is " +
         std::to_string(max_objects);
}

// A box is clipped to the picture, as start-box is; wholly outside it, the library says why.
Added add_box_to(Objects& objects, const Rect& box, int width, int height) {
  const Rect clipped = clip_to_frame(box, width, height);
  return objects.tracker.add_box(clipped.empty() ? box : clipped, width, height);
}

using AddTo = std::function<Added(Objects&, int width, int height)>;

// One start from an application's thread: checked and added under objects_mutex, warned of
// after it (an element warning may run a bus sync handler, which may add an object).
gint add_object(GstProjtrack* self, const std::string& what, const AddTo& add) {
  Added added;
  {
    std::lock_guard<std::mutex> guard(self->state->objects_mutex);
    GST_OBJECT_LOCK(self);
    const int width = self->state->locked.frame_width, height = self->state->locked.frame_height;
    const int max_objects = self->state->locked.settings.max_objects;
    GST_OBJECT_UNLOCK(self);
    Stream* st = self->state->stream.get();
    if (!st || width <= 0 || height <= 0)
      added.why = "no video yet (no caps): give start-boxes or start-points before it flows";
    else if (std::string why = over_limit(st->objects, max_objects); !why.empty())
      added.why = std::move(why);
    else
      added = add(st->objects, width, height);
  }
  if (added) {
    GST_INFO_OBJECT(self, "%s: object %d", what.c_str(), added.id);
  } else {
    GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS,
                        ("%s refused: %s", what.c_str(), added.why.c_str()),
                        ("no object was added; the objects followed go on"));
  }
  return added.id;
}

}  // namespace

void set_start_boxes(GstProjtrack* self, const GValue* value) {
  std::string why;
  const auto tuples = tuples_of(value, 4, "start-boxes", "<x, y, width, height>", why);
  if (!tuples) return refuse_list_locked(self, why);
  std::vector<Rect>& boxes = self->state->locked.settings.start_boxes;
  boxes.clear();
  for (const Tuple& t : *tuples) boxes.push_back({t[0], t[1], t[2], t[3]});
  self->state->locked.restart_objects = true;
}

void get_start_boxes(GstProjtrack* self, GValue* value) {
  for (const Rect& b : self->state->locked.settings.start_boxes)
    append_tuple(value, {b.x, b.y, b.width, b.height});
}

void set_start_points(GstProjtrack* self, const GValue* value) {
  std::string why;
  const auto tuples = tuples_of(value, 2, "start-points", "<x, y>", why);
  if (!tuples) return refuse_list_locked(self, why);
  std::vector<Point2i>& points = self->state->locked.settings.start_points;
  points.clear();
  for (const Tuple& t : *tuples) points.push_back({t[0], t[1]});
  self->state->locked.restart_objects = true;
}

void get_start_points(GstProjtrack* self, GValue* value) {
  for (const Point2i& p : self->state->locked.settings.start_points)
    append_tuple(value, {p.x, p.y});
}

gint add_box(GstProjtrack* self, gint x, gint y, gint width, gint height) {
  const Rect box{x, y, width, height};
  const std::string what = "add-box <" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                           std::to_string(width) + ", " + std::to_string(height) + ">";
  return add_object(self, what, [&](Objects& o, int w, int h) { return add_box_to(o, box, w, h); });
}

gint add_point(GstProjtrack* self, gint x, gint y) {
  const std::string what = "add-point <" + std::to_string(x) + ", " + std::to_string(y) + ">";
  return add_object(self, what, [&](Objects& o, int w, int h) {
    return o.tracker.add_point({x, y}, w, h);
  });
}

void add_clicked(GstProjtrack* self, int x, int y) {
  const std::string what = "click at " + std::to_string(x) + ", " + std::to_string(y);
  add_object(self, what, [&](Objects& o, int w, int h) {
    return o.tracker.add_point({x, y}, w, h);
  });
}

gboolean remove_object(GstProjtrack* self, gint id) {
  bool removed = false;
  {
    std::lock_guard<std::mutex> guard(self->state->objects_mutex);
    if (Stream* st = self->state->stream.get()) {
      removed = st->objects.tracker.remove(id);
      st->objects.last_posted.erase(id);
      st->objects.track_ids.erase(id);
    }
  }
  if (removed)
    GST_INFO_OBJECT(self, "remove-object %d", id);
  else
    GST_ELEMENT_WARNING(self, LIBRARY, SETTINGS,
                        ("remove-object refused: no object of id %d is followed", id),
                        ("the objects followed go on"));
  return removed;
}

std::vector<std::string> restart_objects(Objects& objects, const ElementSettings& s, int width,
                                         int height) {
  objects.tracker.clear();
  objects.last_posted.clear();
  objects.track_ids.clear();
  std::vector<std::string> refused;
  const auto add = [&](const std::string& what, const AddTo& to) {
    std::string why = over_limit(objects, s.max_objects);
    if (why.empty()) why = to(objects, width, height).why;
    if (!why.empty()) refused.push_back(what + " refused: " + why);
  };
  for (const Rect& b : s.start_boxes)
    add("start-boxes entry <" + std::to_string(b.x) + ", " + std::to_string(b.y) + ", " +
            std::to_string(b.width) + ", " + std::to_string(b.height) + ">",
        [&](Objects& o, int w, int h) { return add_box_to(o, b, w, h); });
  for (const Point2i& p : s.start_points)
    add("start-points entry <" + std::to_string(p.x) + ", " + std::to_string(p.y) + ">",
        [&](Objects& o, int w, int h) { return o.tracker.add_point(p, w, h); });
  return refused;
}

}  // namespace projtrack::gst
