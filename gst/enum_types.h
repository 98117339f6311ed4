// The element's enum and flags GTypes (gst-inspect-1.0 shows them): made in enums.cpp from the
// name tables (include/projtrack/names.hpp; updates_table.def and draw_flags_table.def here), each
// registered on its first use.
#pragma once

#include <glib-object.h>

G_BEGIN_DECLS

#define GST_TYPE_PROJTRACK_METHOD (gst_projtrack_method_get_type())
GType gst_projtrack_method_get_type(void);

#define GST_TYPE_PROJTRACK_EDGE_DETECTOR (gst_projtrack_edge_detector_get_type())
GType gst_projtrack_edge_detector_get_type(void);

#define GST_TYPE_PROJTRACK_ACQUISITION (gst_projtrack_acquisition_get_type())
GType gst_projtrack_acquisition_get_type(void);

#define GST_TYPE_PROJTRACK_OBJECT_MODEL (gst_projtrack_object_model_get_type())
GType gst_projtrack_object_model_get_type(void);

#define GST_TYPE_PROJTRACK_UPDATES (gst_projtrack_updates_get_type())
GType gst_projtrack_updates_get_type(void);

#define GST_TYPE_PROJTRACK_DRAW_FLAGS (gst_projtrack_draw_flags_get_type())
GType gst_projtrack_draw_flags_get_type(void);

G_END_DECLS
