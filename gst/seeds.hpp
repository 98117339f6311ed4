// Where a track starts: the inner point or box a user gives (the inner-point-x/-y and start-box
// properties, the track-point, track-box and reset signals, a click), checked (a malformed box is
// refused, and why is said), turned into the command the streaming thread applies before its next
// frame; and where the tracker is now (current-inner-point-x/-y). Functions named *_locked, and the
// property handlers, are called with the object lock held.
#pragma once

#include <gst/gst.h>

#include <string>

#include "gstprojtrack.h"
#include "projtrack/geometry.hpp"
#include "projtrack/tracker.hpp"
#include "settings.hpp"

namespace projtrack::gst {

// A whole point seeds the track there; a point with a coordinate of -1 stops it, unless
// `awaiting_coordinate` (a property just gave the first coordinate of a new point: the track goes
// on until the second comes).
void set_inner_point_locked(GstProjtrack* self, int x, int y, bool awaiting_coordinate = false);
// The track starts in `box` on the next frame; an empty box stops it.
void set_box_locked(GstProjtrack* self, const Rect& box);
// The frames changed size: the point and box given follow, and the objects' lists (start-points,
// start-boxes), so that a restart finds the objects.
void rescale_seeds_locked(GstProjtrack* self, int width, int height, int new_width, int new_height);
// A pixel of a width × height frame in the new_width × new_height one (clamped at 0).
Point2i rescaled_point(Point2i p, int width, int height, int new_width, int new_height);
// The part of `box` in a width × height frame, scaled to cover the same pixels of the new one;
// a box wholly outside the old frame (never applied) is kept as it is.
Rect rescaled_box(const Rect& box, int width, int height, int new_width, int new_height);
// A restart (caps change, stop/start) begins again from the last inner point or box given.
void reseed_locked(GstProjtrack* self);
// Tells the app that the seed changed: inner-point-x/-y and start-box. Without the lock.
void notify_inner_point(GstProjtrack* self);

// The property table's handlers (property_table.def).
void set_inner_point_x(GstProjtrack* self, const GValue* value);
void get_inner_point_x(GstProjtrack* self, GValue* value);
void set_inner_point_y(GstProjtrack* self, const GValue* value);
void get_inner_point_y(GstProjtrack* self, GValue* value);
void set_start_box(GstProjtrack* self, const GValue* value);
void get_start_box(GstProjtrack* self, GValue* value);
void get_current_inner_point_x(GstProjtrack* self, GValue* value);
void get_current_inner_point_y(GstProjtrack* self, GValue* value);

// The action signals: an app starts or stops a track in one call (no race between two
// properties).
void track_point(GstProjtrack* self, gint x, gint y);
void track_box(GstProjtrack* self, gint x, gint y, gint width, gint height);
void reset(GstProjtrack* self);

// The streaming thread applies `command` (the seed given last, in `s`) before a width × height
// frame. A box is clipped to the picture; one wholly outside it is not applied, and the returned
// text says so (empty when all went well).
std::string apply_seed(Tracker& tracker, SeedCommand command, const ElementSettings& s, int width,
                       int height);

}  // namespace projtrack::gst
