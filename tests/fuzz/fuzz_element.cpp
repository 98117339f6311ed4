// libFuzzer target over the element's frame path, in GstHarness: buffers of every format and of
// small random sizes whose layout may lie — a video meta with offsets and strides beyond the
// memory, negative (bottom-up) or zero strides, another size or format than the caps; a buffer
// too short or too long without a meta; planes cut across up to four memory blocks — pushed with
// the overlay on or off, any method, with or without an inner point. Each block is an allocation
// of its own, exactly its size, so AddressSanitizer sees any access outside it. It checks the
// element's promises, not just "no crash": every buffer comes out with one message of a known
// status and finite numbers; a buffer refused as `invalid-image` with a `reason` comes out byte
// for byte as it went in; a buffer laid out as its caps say is never refused.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "projtrack/method.hpp"

namespace {

using projtrack::fuzz::check;
using projtrack::fuzz::Input;
using Bytes = std::vector<std::uint8_t>;

constexpr GstVideoFormat kFormats[] = {
    GST_VIDEO_FORMAT_GRAY8, GST_VIDEO_FORMAT_I420, GST_VIDEO_FORMAT_YV12, GST_VIDEO_FORMAT_NV12,
    GST_VIDEO_FORMAT_NV21,  GST_VIDEO_FORMAT_Y42B, GST_VIDEO_FORMAT_Y444, GST_VIDEO_FORMAT_YUY2,
    GST_VIDEO_FORMAT_UYVY,  GST_VIDEO_FORMAT_BGRx, GST_VIDEO_FORMAT_RGBx, GST_VIDEO_FORMAT_xRGB,
    GST_VIDEO_FORMAT_xBGR,  GST_VIDEO_FORMAT_BGRA, GST_VIDEO_FORMAT_RGBA, GST_VIDEO_FORMAT_ARGB,
    GST_VIDEO_FORMAT_ABGR,  GST_VIDEO_FORMAT_BGR,  GST_VIDEO_FORMAT_RGB};
constexpr int kFormatCount = sizeof(kFormats) / sizeof(kFormats[0]);

const std::set<std::string> kStatuses = {
    "ok",          "reached-border", "covers-frame",        "lost",
    "searching",   "no-inner-point", "inner-point-outside", "inner-point-on-edge",
    "empty-image", "invalid-image",  "invalid-parameters",  "over-budget",
    "interrupted"};

// The element from the build (a path meson gives), scanned in this process: the plugin is
// instrumented like the target.
void init_gstreamer() {
  static const bool done = [] {
    g_setenv("GST_PLUGIN_PATH", PROJTRACK_PLUGIN_DIR, TRUE);
    g_setenv("GST_REGISTRY_1_0", PROJTRACK_FUZZ_REGISTRY, TRUE);
    g_setenv("GST_REGISTRY_FORK", "no", TRUE);
    gst_init(nullptr, nullptr);
    return true;
  }();
  (void)done;
}

// Where a plane's rows start and how far apart they are, as a meta would say.
struct Layout {
  bool meta = false;
  bool honest = true;  // the caps' own layout: must never be refused
  GstVideoFormat format = GST_VIDEO_FORMAT_UNKNOWN;
  int width = 0, height = 0;
  std::vector<gsize> offsets;
  std::vector<gint> strides;
  gsize size = 0;
  std::vector<gsize> cuts;  // where the buffer's bytes are split into memory blocks
};

int plane_rows(const GstVideoInfo& info, guint plane) {
  gint comps[GST_VIDEO_MAX_COMPONENTS];
  gst_video_format_info_component(info.finfo, plane, comps);
  return GST_VIDEO_INFO_COMP_HEIGHT(&info, comps[0]);
}

Layout any_layout(Input& in, const GstVideoInfo& info) {
  Layout l;
  l.format = GST_VIDEO_INFO_FORMAT(&info);
  l.width = GST_VIDEO_INFO_WIDTH(&info);
  l.height = GST_VIDEO_INFO_HEIGHT(&info);
  l.size = GST_VIDEO_INFO_SIZE(&info);
  const gsize caps_size = l.size;
  l.meta = in.in(0, 2) != 0;
  switch (in.in(0, 3)) {  // the buffer's size: mostly the caps' size
    case 1:
      l.size += in.in(1, 64);
      break;
    case 2:
      l.size -= std::min<gsize>(l.size, in.in(1, 4096));
      l.honest = false;
      break;
    default:
      break;
  }
  if (l.meta) {
    for (guint i = 0; i < GST_VIDEO_INFO_N_PLANES(&info); ++i) {
      gint64 offset = info.offset[i];
      gint stride = info.stride[i];
      switch (in.in(0, 9)) {
        case 1:  // bottom-up: the same bytes, rows the other way
          offset += static_cast<gint64>(plane_rows(info, i) - 1) * stride;
          stride = -stride;
          break;
        case 2:
          stride = 0;
          l.honest = false;
          break;
        case 3:
          stride += in.in(-8, 8);
          l.honest = false;
          break;
        case 4:
          stride = in.in(-4096, 4096);
          l.honest = false;
          break;
        case 5:
          stride = in.in(0, 1) ? INT_MAX : INT_MIN;
          l.honest = false;
          break;
        case 6:
          offset += in.in(-64, 64);
          l.honest = false;
          break;
        case 7:
          offset = in.in(0, 1) ? in.u16() : G_MAXSSIZE - in.u16();
          l.honest = false;
          break;
        default:
          break;
      }
      l.offsets.push_back(static_cast<gsize>(std::max<gint64>(offset, 0)));
      l.strides.push_back(stride);
    }
    switch (in.in(0, 9)) {  // the meta's own size and format: mostly the caps'
      case 1:
        l.width = std::max(0, l.width + in.in(-2, 2));
        l.height = std::max(0, l.height + in.in(-2, 2));
        l.honest = false;
        break;
      case 2:
        l.format = kFormats[in.in(0, kFormatCount - 1)];
        l.honest = l.honest && l.format == GST_VIDEO_INFO_FORMAT(&info);
        break;
      default:
        break;
    }
    // A meta's planes of another format than the caps' are as many as that format has.
    const guint planes = GST_VIDEO_FORMAT_INFO_N_PLANES(gst_video_format_get_info(l.format));
    l.offsets.resize(planes, 0);
    l.strides.resize(planes, l.strides.empty() ? 0 : l.strides.back());
  }
  if (l.size < caps_size && !l.meta) l.honest = false;
  for (int n = in.in(0, 3); n > 0; --n) l.cuts.push_back(in.in(0, 65535) % (l.size + 1));
  std::sort(l.cuts.begin(), l.cuts.end());
  return l;
}

// The buffer: each memory block a malloc of its own size, so that ASan bounds it exactly.
GstBuffer* make_buffer(Layout& l, const Bytes& bytes) {
  GstBuffer* buf = gst_buffer_new();
  gsize from = 0;
  std::vector<gsize> ends = l.cuts;
  ends.push_back(l.size);
  for (gsize to : ends) {
    if (to <= from) continue;
    auto* block = static_cast<std::uint8_t*>(g_malloc(to - from));
    std::memcpy(block, bytes.data() + from, to - from);
    gst_buffer_append_memory(buf, gst_memory_new_wrapped(static_cast<GstMemoryFlags>(0), block,
                                                         to - from, 0, to - from, block, g_free));
    from = to;
  }
  if (l.meta) {
    gst_buffer_add_video_meta_full(buf, GST_VIDEO_FRAME_FLAG_NONE, l.format, l.width, l.height,
                                   l.offsets.size(), l.offsets.data(), l.strides.data());
  }
  return buf;
}

Bytes bytes_of(GstBuffer* buf) {
  Bytes b(gst_buffer_get_size(buf));
  if (!b.empty()) gst_buffer_extract(buf, 0, b.data(), b.size());  // an empty one has no data
  return b;
}

void check_message(const GstStructure* s, bool unchanged, bool honest) {
  const char* status = gst_structure_get_string(s, "status");
  check(status && kStatuses.count(status), "a known status");
  const bool refused =
      std::string(status) == "invalid-image" && gst_structure_has_field(s, "reason");
  check(!refused || unchanged, "a refused buffer passes untouched");
  check(!refused || !honest, "a buffer in the caps' own layout is read");
  for (int i = 0; i < gst_structure_n_fields(s); ++i) {
    const GValue* v = gst_structure_get_value(s, gst_structure_nth_field_name(s, i));
    if (G_VALUE_HOLDS_DOUBLE(v)) check(std::isfinite(g_value_get_double(v)), "finite numbers");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  init_gstreamer();
  Input in(data, size);
  GstVideoInfo info;
  const GstVideoFormat format = kFormats[in.in(0, kFormatCount - 1)];
  if (!gst_video_info_set_format(&info, format, in.in(1, 64), in.in(1, 48))) return 0;
  const bool draw = in.in(0, 1);
  const int method = in.in(0, projtrack::kMethodCount - 1);
  const int seed = in.in(0, 2);  // none (auto acquisition), the centre, anywhere
  const int frames = in.in(1, 3);
  Layout layout = any_layout(in, info);
  Bytes bytes(layout.size);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = in.left() ? in.byte() : static_cast<std::uint8_t>(i * 7 + (i >> 6) * 13);

  if (g_getenv("PROJTRACK_FUZZ_VERBOSE")) {  // what an input is, when replaying a crash
    std::fprintf(stderr, "%s %dx%d, %zu bytes in %zu cuts, draw %d, method %d, seed %d, %d frames",
                 gst_video_format_to_string(format), info.width, info.height, layout.size,
                 layout.cuts.size(), draw, method, seed, frames);
    if (layout.meta) {
      std::fprintf(stderr, "; meta %s %dx%d", gst_video_format_to_string(layout.format),
                   layout.width, layout.height);
      for (std::size_t i = 0; i < layout.offsets.size(); ++i)
        std::fprintf(stderr, ", plane %zu at %zu stride %d", i, layout.offsets[i],
                     layout.strides[i]);
    }
    std::fprintf(stderr, "\n");
  }
  GstHarness* h = gst_harness_new("projtrack");
  check(h != nullptr, "the element loads");
  GstBus* bus = gst_bus_new();
  gst_element_set_bus(h->element, bus);
  g_object_set(h->element, "draw", draw, nullptr);
  gst_util_set_object_arg(G_OBJECT(h->element), "method",
                          projtrack::method_name(projtrack::kAllMethods[method]).data());
  if (seed) {
    const int x = seed == 1 ? info.width / 2 : in.in(0, 80);
    const int y = seed == 1 ? info.height / 2 : in.in(0, 60);
    g_object_set(h->element, "inner-point-x", x, "inner-point-y", y, nullptr);
  }
  GstCaps* caps = gst_video_info_to_caps(&info);
  gst_harness_set_src_caps(h, caps);
  for (int i = 0; i < frames; ++i) {
    GstBuffer* buf = make_buffer(layout, bytes);
    GST_BUFFER_PTS(buf) = i * GST_SECOND / 30;
    check(gst_harness_push(h, buf) == GST_FLOW_OK, "every buffer is accepted");
    GstBuffer* out = gst_harness_pull(h);
    check(out != nullptr, "every buffer comes out");
    const bool unchanged = bytes_of(out) == bytes;
    gst_buffer_unref(out);
    int messages = 0;
    while (GstMessage* m = gst_bus_pop_filtered(bus, GST_MESSAGE_ELEMENT)) {
      if (gst_message_has_name(m, "projtrack")) {
        ++messages;
        check_message(gst_message_get_structure(m), unchanged, layout.honest);
      }
      gst_message_unref(m);
    }
    check(messages == 1, "one message per buffer");
  }
  gst_harness_teardown(h);
  gst_bus_set_flushing(bus, TRUE);
  gst_object_unref(bus);
  return 0;
}
