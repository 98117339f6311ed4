#include "events.hpp"

#include <gst/video/navigation.h>

#include <cmath>

#include "element.hpp"
#include "objects.hpp"
#include "seeds.hpp"

namespace projtrack::gst {

gboolean start(GstBaseTransform* trans) {
  GST_PROJTRACK(trans)->state->interrupt.store(false);
  return TRUE;
}

// PAUSED → READY waits for the streaming thread to leave the element (the pads are deactivated
// under its stream lock): the flag makes a frame in progress stop at the tracker's next
// checkpoint instead of running to its end. That frame passes through with status=interrupted.
void on_state_change(GstProjtrack* self, GstStateChange transition) {
  if (transition == GST_STATE_CHANGE_PAUSED_TO_READY) {
    GST_DEBUG_OBJECT(self, "stopping: a frame in progress is interrupted");
    self->state->interrupt.store(true);
  }
}

void on_sink_event(GstProjtrack* self, GstEvent* event) {
  if (GST_EVENT_TYPE(event) == GST_EVENT_FLUSH_START) {
    GST_DEBUG_OBJECT(self, "flushing: a frame in progress is interrupted");
    self->state->interrupt.store(true);
  } else if (GST_EVENT_TYPE(event) == GST_EVENT_FLUSH_STOP) {
    // A flush is a seek (or a jump): the frames that follow show another moment, where the old
    // track's inner point means nothing. The track restarts from the seed given, or searches.
    GST_DEBUG_OBJECT(self, "flushed: the track restarts from the seed given, if any");
    GST_OBJECT_LOCK(self);
    reseed_locked(self);
    self->state->locked.restart_objects = true;  // the objects too, from their lists
    GST_OBJECT_UNLOCK(self);
    self->state->interrupt.store(false);
  }
}

// Clicks outside the picture (a letterboxed window's borders) are ignored.
void on_src_event(GstProjtrack* self, GstEvent* event) {
  if (GST_EVENT_TYPE(event) != GST_EVENT_NAVIGATION ||
      gst_navigation_event_get_type(event) != GST_NAVIGATION_EVENT_MOUSE_BUTTON_PRESS)
    return;
  gint button = 0;
  gdouble x = 0, y = 0;
  if (!gst_navigation_event_parse_mouse_button_event(event, &button, &x, &y) ||
      (button != 1 && button != 3) || !std::isfinite(x) || !std::isfinite(y))
    return;
  GST_OBJECT_LOCK(self);
  const double px = std::round(x), py = std::round(y);
  const bool in_picture = px >= 0 && py >= 0 && px < self->state->locked.frame_width &&
                          py < self->state->locked.frame_height;
  if (button == 1 && in_picture && self->state->locked.settings.click_adds) {
    GST_OBJECT_UNLOCK(self);
    // click-adds: the object clicked joins those followed; the single track is left alone.
    add_clicked(self, static_cast<int>(px), static_cast<int>(py));
    return;
  }
  const bool changed = button == 3 || in_picture;
  if (button == 3)
    set_inner_point_locked(self, -1, -1);
  else if (in_picture)
    set_inner_point_locked(self, static_cast<int>(px), static_cast<int>(py));
  const int sx = self->state->locked.settings.inner_point_x,
            sy = self->state->locked.settings.inner_point_y;
  GST_OBJECT_UNLOCK(self);
  GST_INFO_OBJECT(self, "click (button %d) at %.1f, %.1f: %s inner point %d, %d", button, x, y,
                  changed ? "new" : "outside the picture, kept the", sx, sy);
  if (changed) notify_inner_point(self);
}

}  // namespace projtrack::gst
