// What the element does with events before they go on: a state change or a flush interrupts a
// frame in progress (a flush also restarts the track), and a click seeds or stops the track. The
// element's virtual methods (gstprojtrack.cpp) call these, then chain up.
#pragma once

#include <gst/base/gstbasetransform.h>

#include "gstprojtrack.h"

namespace projtrack::gst {

// Streaming starts (READY → PAUSED): a stop asked before is over.
gboolean start(GstBaseTransform* trans);
// PAUSED → READY interrupts a frame in progress.
void on_state_change(GstProjtrack* self, GstStateChange transition);
// A flush interrupts a frame in progress; its end lets the next frames run, the track restarted
// from the seed given (or searching again).
void on_sink_event(GstProjtrack* self, GstEvent* event);
// A left click in the picture seeds the track there; a right click stops it.
void on_src_event(GstProjtrack* self, GstEvent* event);

}  // namespace projtrack::gst
