// The projtrack element: edges + the chosen estimator on every buffer.
#pragma once

#include <gst/video/gstvideofilter.h>
#include <gst/video/video.h>

G_BEGIN_DECLS

#define GST_TYPE_PROJTRACK (gst_projtrack_get_type())
G_DECLARE_FINAL_TYPE(GstProjtrack, gst_projtrack, GST, PROJTRACK, GstVideoFilter)

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

GST_ELEMENT_REGISTER_DECLARE(projtrack);

G_END_DECLS
