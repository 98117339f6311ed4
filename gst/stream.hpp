// The stream through the element: per-stream state created when the caps are set and dropped at
// stop, and every buffer through the tracker (the GstVideoFilter and GstBaseTransform virtual
// methods that do not chain up).
#pragma once

#include <gst/base/gstbasetransform.h>
#include <gst/video/video.h>

namespace projtrack::gst {

gboolean set_info(GstVideoFilter* filter, GstCaps* in_caps, GstVideoInfo* in_info,
                  GstCaps* out_caps, GstVideoInfo* out_info);
gboolean stop(GstBaseTransform* trans);
GstFlowReturn transform_ip(GstBaseTransform* trans, GstBuffer* buffer);

}  // namespace projtrack::gst
