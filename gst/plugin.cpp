// The projtrack plugin: one element.
#include <gst/gst.h>

#include "gstprojtrack.h"

static gboolean plugin_init(GstPlugin* plugin) { return GST_ELEMENT_REGISTER(projtrack, plugin); }

GST_PLUGIN_DEFINE(
    GST_VERSION_MAJOR, GST_VERSION_MINOR, projtrack,
    "Object projection feature tracking (centroid, area) from edges and an inner point",
    plugin_init, PACKAGE_VERSION, "LGPL", "projtrack", "Unknown package origin")
