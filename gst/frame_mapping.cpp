#include "frame_mapping.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace projtrack::gst {

namespace {

// What the element reads of a plane: its rows, and the bytes of one row from the plane's start
// to the end of its last sample (every component stored in it).
struct PlaneShape {
  gint64 rows = 0, row_bytes = 0;
};

PlaneShape plane_shape(const GstVideoFormatInfo* f, guint plane, int width, int height) {
  gint comps[GST_VIDEO_MAX_COMPONENTS];
  gst_video_format_info_component(f, plane, comps);
  PlaneShape s;
  for (int k = 0; k < GST_VIDEO_MAX_COMPONENTS && comps[k] >= 0; ++k) {
    const int c = comps[k];
    const gint64 w = GST_VIDEO_FORMAT_INFO_SCALE_WIDTH(f, c, width);
    const gint64 h = GST_VIDEO_FORMAT_INFO_SCALE_HEIGHT(f, c, height);
    const gint64 bytes = GST_VIDEO_FORMAT_INFO_POFFSET(f, c) +
                         (w - 1) * GST_VIDEO_FORMAT_INFO_PSTRIDE(f, c) +
                         (GST_VIDEO_FORMAT_INFO_DEPTH(f, c) + 7) / 8;
    s.rows = std::max(s.rows, h);
    s.row_bytes = std::max(s.row_bytes, bytes);
  }
  return s;
}

// The bytes [lo, hi) that a plane whose first row starts at `first` covers: with a negative
// stride the last row lies below the first.
struct Span {
  gint64 lo, hi;
};

Span plane_span(const PlaneShape& s, gint64 first, gint64 stride) {
  const gint64 last = (s.rows - 1) * stride;
  return {first + std::min<gint64>(0, last), first + std::max<gint64>(0, last) + s.row_bytes};
}

FrameMapping refuse(const char* reason, gchar* detail) {
  FrameMapping m;
  m.reason = reason;
  m.detail = detail;
  g_free(detail);
  return m;
}

// The layout's own faults, whatever the memory: rows that overlap, planes too large to address.
const char* layout_fault(const PlaneShape& s, gint64 stride) {
  if (s.rows > 1 && std::abs(stride) < s.row_bytes) return "rows-overlap";
  if (s.rows * std::max(std::abs(stride), s.row_bytes) > kMaxPlaneBytes) return "too-large";
  return nullptr;
}

}  // namespace

FrameMapping map_frame_checked(GstVideoFrame* frame, const GstVideoInfo* info, GstBuffer* buffer,
                               GstMapFlags flags) {
  const GstVideoFormatInfo* f = info->finfo;
  const int width = GST_VIDEO_INFO_WIDTH(info), height = GST_VIDEO_INFO_HEIGHT(info);
  const guint n_planes = GST_VIDEO_INFO_N_PLANES(info);
  const gsize size = gst_buffer_get_size(buffer);
  const GstVideoMeta* meta = gst_buffer_get_video_meta(buffer);
  // gst_video_frame_map() asserts these (a critical, not a refusal): say it first.
  if (meta &&
      (meta->format != GST_VIDEO_INFO_FORMAT(info) || meta->n_planes != n_planes ||
       meta->width < static_cast<guint>(width) || meta->height < static_cast<guint>(height))) {
    return refuse(
        "meta-mismatch",
        g_strdup_printf("video meta %s %ux%u in %u planes, caps %s %dx%d in %u planes",
                        gst_video_format_to_string(meta->format), meta->width, meta->height,
                        meta->n_planes, GST_VIDEO_INFO_NAME(info), width, height, n_planes));
  }
  if (!meta && size < GST_VIDEO_INFO_SIZE(info)) {
    return refuse("buffer-too-small",
                  g_strdup_printf("buffer of %" G_GSIZE_FORMAT
                                  " bytes, the caps' frame needs %" G_GSIZE_FORMAT,
                                  size, GST_VIDEO_INFO_SIZE(info)));
  }
  bool spans_blocks = false;
  for (guint i = 0; i < n_planes; ++i) {
    const gsize offset = meta ? meta->offset[i] : info->offset[i];
    const gint64 stride = meta ? meta->stride[i] : info->stride[i];
    const PlaneShape s = plane_shape(f, i, width, height);
    if (const char* fault = layout_fault(s, stride)) {
      return refuse(fault,
                    g_strdup_printf("plane %u: %" G_GINT64_FORMAT " rows of %" G_GINT64_FORMAT
                                    " bytes, %" G_GINT64_FORMAT " bytes apart",
                                    i, s.rows, s.row_bytes, stride));
    }
    const Span span = plane_span(s, static_cast<gint64>(std::min(offset, size)), stride);
    if (offset > size || span.lo < 0 || span.hi > static_cast<gint64>(size)) {
      return refuse("plane-outside-buffer",
                    g_strdup_printf("plane %u: offset %" G_GSIZE_FORMAT ", stride %" G_GINT64_FORMAT
                                    ", %" G_GINT64_FORMAT " rows need bytes %" G_GINT64_FORMAT
                                    " to %" G_GINT64_FORMAT ", the buffer has %" G_GSIZE_FORMAT,
                                    i, offset, stride, s.rows, span.lo, span.hi, size));
    }
    guint idx = 0, blocks = 0;
    gsize skip = 0;
    if (meta && gst_buffer_find_memory(buffer, span.lo, span.hi - span.lo, &idx, &blocks, &skip) &&
        blocks > 1)
      spans_blocks = true;
  }
  FrameMapping result;
  // With a meta, each plane is mapped from the one block holding its first row: a plane that
  // crosses blocks is made contiguous (one copy; the offsets stay those of the whole buffer).
  if (spans_blocks) {
    if (!gst_buffer_is_writable(buffer))
      return refuse("plane-outside-mapping",
                    g_strdup("a plane spans memory blocks of a buffer that cannot be merged"));
    gst_buffer_replace_all_memory(buffer, gst_buffer_get_all_memory(buffer));
    result.merged = true;
  }
  if (!gst_video_frame_map(frame, info, buffer, flags))
    return refuse("map-failed", g_strdup("gst_video_frame_map() failed"));
  frame->info.width = width;  // a meta may describe padding below or right of the picture
  frame->info.height = height;
  // What was mapped may still differ from what the meta promised (a custom map function).
  for (guint i = 0; i < n_planes; ++i) {
    const GstMapInfo& map = frame->meta ? frame->map[i] : frame->map[0];
    const gint64 first = static_cast<gint64>(reinterpret_cast<std::uintptr_t>(frame->data[i]) -
                                             reinterpret_cast<std::uintptr_t>(map.data));
    const Span span = plane_span(plane_shape(f, i, width, height), first, frame->info.stride[i]);
    if (span.lo < 0 || span.hi > static_cast<gint64>(map.size)) {
      gst_video_frame_unmap(frame);
      return refuse("plane-outside-mapping",
                    g_strdup_printf("plane %u needs bytes %" G_GINT64_FORMAT " to %" G_GINT64_FORMAT
                                    " of a mapping of %" G_GSIZE_FORMAT,
                                    i, span.lo, span.hi, map.size));
    }
  }
  return result;
}

}  // namespace projtrack::gst
