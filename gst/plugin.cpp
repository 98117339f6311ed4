// The projtrack plugin: one element.
#include <gst/gst.h>

#include "gstprojtrack.h"

static gboolean plugin_init(GstPlugin* plugin) { return GST_ELEMENT_REGISTER(projtrack, plugin); }

GST_PLUGIN_DEFINE(GST_VERSION_MAJOR, GST_VERSION_MINOR, projtrack,
                  "Tracks an object in video: centroid, area, bounding box and a 3D pointer, "
                  "from its edges, colours and one inner point",
                  plugin_init, PACKAGE_VERSION, "LGPL", GST_PACKAGE_NAME, GST_PACKAGE_ORIGIN)
