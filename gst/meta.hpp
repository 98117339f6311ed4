// GstProjtrackMeta (gstprojtrackmeta.h): the features of a tracked frame on its buffer, as a
// custom meta whose transform function keeps them true to the frame that carries them, through
// the elements an application puts after projtrack.
#pragma once

#include <gst/gst.h>

namespace projtrack::gst {

// Registers the meta (once, from any thread) and returns its info.
const GstMetaInfo* projtrack_meta_info();

// Adds a GstProjtrackMeta holding a copy of the fields of `features` to `buffer` (writable).
void add_projtrack_meta(GstBuffer* buffer, const GstStructure* features);

// `features` (a frame of in_width × in_height) in a frame of out_width × out_height, as if the
// picture were scaled: positions and the box follow the pixels, the area grows with the frame's,
// the 3D pointer (relative to the frame) stays. Null when a size is not positive.
GstStructure* scaled_features(const GstStructure* features, int in_width, int in_height,
                              int out_width, int out_height);

}  // namespace projtrack::gst
