// Maps a buffer as a video frame only when every plane the element reads lies inside the memory
// mapped for it. gst_video_frame_map() trusts a GstVideoMeta's offsets and strides, and with a meta
// maps only the memory block that holds a plane's first byte: a meta that lies, or a plane split
// across blocks, would otherwise send every reader past the end of the mapping.
#pragma once

#include <gst/video/video.h>

#include <string>

namespace projtrack::gst {

// Planes larger than this many bytes (rows × |stride|) are refused: GStreamer's strides and the
// overlay's offsets are ints. For GRAY8 it bounds a frame below 2^31 pixels.
inline constexpr gint64 kMaxPlaneBytes = G_MAXINT;

struct FrameMapping {
  // Null when the frame is mapped; else a stable token for the message's `reason`:
  // buffer-too-small, meta-mismatch, rows-overlap, too-large, plane-outside-buffer,
  // plane-outside-mapping, map-failed.
  const char* reason = nullptr;
  std::string detail;   // the numbers behind the reason, in words
  bool merged = false;  // the buffer's memory blocks were merged so that a plane is contiguous

  bool ok() const { return reason == nullptr; }
};

// Checks `buffer` (its video meta if it has one, else the caps' layout in `info`) before mapping:
// every plane's rows must lie inside the buffer and not overlap (|stride| at least a row's bytes
// unless the plane has one row; negative strides, bottom-up rows, are accepted). A plane that
// spans memory blocks has the buffer's memory merged first (`buffer` must be writable). Then maps
// it with gst_video_frame_map() and checks every plane against what was actually mapped. The
// frame has the caps' width and height even when the meta describes a larger (padded) one. On
// failure nothing is left mapped and nothing was read.
FrameMapping map_frame_checked(GstVideoFrame* frame, const GstVideoInfo* info, GstBuffer* buffer,
                               GstMapFlags flags);

}  // namespace projtrack::gst
