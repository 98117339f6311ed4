// The projtrack element: edges + the chosen estimator on every buffer.
#pragma once

#include <gst/video/gstvideofilter.h>
#include <gst/video/video.h>

G_BEGIN_DECLS

#define GST_TYPE_PROJTRACK (gst_projtrack_get_type())
G_DECLARE_FINAL_TYPE(GstProjtrack, gst_projtrack, GST, PROJTRACK, GstVideoFilter)

GST_ELEMENT_REGISTER_DECLARE(projtrack);

G_END_DECLS
