// Where the objects followed at once come from: the start-boxes and start-points properties (their
// tuples checked, a malformed one refused and named), the add-box, add-point and remove-object
// action signals, a click with click-adds; and what the streaming thread does with the lists
// before a frame. Property handlers are called with the object lock held; the rest without it.
#pragma once

#include <gst/gst.h>

#include <string>
#include <vector>

#include "gstprojtrack.h"
#include "settings.hpp"

namespace projtrack::gst {

struct Objects;

// The property table's handlers (property_table.def).
void set_start_boxes(GstProjtrack* self, const GValue* value);
void get_start_boxes(GstProjtrack* self, GValue* value);
void set_start_points(GstProjtrack* self, const GValue* value);
void get_start_points(GstProjtrack* self, GValue* value);

// The action signals: the new object's id (0 when refused: an element warning says why), and
// whether object `id` was followed (FALSE, with a warning, when there was none of that id).
gint add_box(GstProjtrack* self, gint x, gint y, gint width, gint height);
gint add_point(GstProjtrack* self, gint x, gint y);
gboolean remove_object(GstProjtrack* self, gint id);

// A left click at (x, y) with click-adds: the object there is added (without the object lock).
void add_clicked(GstProjtrack* self, int x, int y);

// The streaming thread, before a width × height frame (objects_mutex held): every object is
// dropped and the lists' starts added anew. Returns why each refused start was refused.
std::vector<std::string> restart_objects(Objects& objects, const ElementSettings& s, int width,
                                         int height);

}  // namespace projtrack::gst
