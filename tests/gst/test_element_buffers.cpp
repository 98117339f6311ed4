// The element on buffers whose layout does not match their caps: video metas that claim more
// than the memory holds, planes split across memory blocks, bottom-up and zero strides, truncated
// buffers and caps of more than 2^31 pixels. A buffer that does not fit must pass through with its
// bytes unchanged, without ROI meta, and with a message `status=invalid-image` and a `reason`;
// one that fits (bottom-up, split) must be tracked exactly as the same picture laid out plainly.
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace {

struct GstEnvironment : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
};
const auto* const kGstEnvironment = ::testing::AddGlobalTestEnvironment(new GstEnvironment);

using Bytes = std::vector<std::uint8_t>;

// A bright disc off the frame's centre (so that a picture read upside down tracks elsewhere).
struct Disc {
  int width = 96, height = 72, cx = 36, cy = 26, radius = 14;
  bool inside(int x, int y) const {
    return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= radius * radius;
  }
  std::string caps(const char* format) const {
    return "video/x-raw,format=" + std::string(format) + ",width=" + std::to_string(width) +
           ",height=" + std::to_string(height) + ",framerate=30/1";
  }
  // One plane, top-down rows `stride` bytes apart; `sub` halves both axes (I420's chroma).
  Bytes plane(int stride, bool sub, std::uint8_t in, std::uint8_t out) const {
    const int w = sub ? (width + 1) / 2 : width, h = sub ? (height + 1) / 2 : height;
    Bytes b(static_cast<std::size_t>(stride) * h, 0x5A);  // padding: not a picture value
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        b[y * stride + x] = inside(sub ? 2 * x : x, sub ? 2 * y : y) ? in : out;
    return b;
  }
  Bytes luma(int stride) const { return plane(stride, false, 220, 40); }
};

// The rows of a plane of `rows` rows in reverse order (a bottom-up layout of the same picture).
Bytes upside_down(const Bytes& plane, int rows) {
  const std::size_t stride = plane.size() / rows;
  Bytes b(plane.size());
  for (int y = 0; y < rows; ++y)
    std::copy_n(plane.begin() + y * stride, stride, b.begin() + (rows - 1 - y) * stride);
  return b;
}

// Planes one after the other.
Bytes joined(std::initializer_list<Bytes> planes) {
  Bytes b;
  for (const Bytes& p : planes) b.insert(b.end(), p.begin(), p.end());
  return b;
}

GstBuffer* buffer_of(const Bytes& bytes) {
  return gst_buffer_new_memdup(bytes.data(), bytes.size());
}

// The same bytes in two memory blocks, cut at `at`.
GstBuffer* split_buffer(const Bytes& bytes, std::size_t at) {
  GstBuffer* buf = gst_buffer_new_memdup(bytes.data(), at);
  GstBuffer* tail = gst_buffer_new_memdup(bytes.data() + at, bytes.size() - at);
  return gst_buffer_append(buf, tail);
}

void add_meta(GstBuffer* buf, GstVideoFormat format, int w, int h, std::vector<gsize> offsets,
              std::vector<gint> strides) {
  gst_buffer_add_video_meta_full(buf, GST_VIDEO_FRAME_FLAG_NONE, format, w, h, offsets.size(),
                                 offsets.data(), strides.data());
}

Bytes bytes_of(GstBuffer* buf) {
  Bytes b(gst_buffer_get_size(buf));
  gst_buffer_extract(buf, 0, b.data(), b.size());
  return b;
}

// What came out of the element for the last of the buffers pushed.
struct Outcome {
  GstFlowReturn flow = GST_FLOW_ERROR;
  std::string status, reason;
  double cx = NAN, cy = NAN, area = NAN;
  bool unchanged = false;  // the last buffer's bytes are the same after the element
  bool roi = false;        // the last buffer carries an ROI meta
  int messages = 0, warnings = 0, errors = 0;
  guint memories = 0;  // memory blocks of the last buffer after the element
  Bytes out;           // the last buffer's bytes after the element (unless `skip_bytes`)
};

struct Case {
  std::string caps;
  std::function<GstBuffer*()> make;
  int frames = 3;
  bool draw = true;
  bool skip_bytes = false;  // for buffers too big to copy: they are mapped read-only anyway
};

Outcome run(const Case& c, int seed_x = 36, int seed_y = 26) {
  Outcome o;
  GstHarness* h = gst_harness_new("projtrack");
  EXPECT_NE(h, nullptr) << "is GST_PLUGIN_PATH set to the build's gst folder?";
  if (!h) return o;
  GstBus* bus = gst_bus_new();
  gst_element_set_bus(h->element, bus);
  g_object_set(h->element, "draw", c.draw, "inner-point-x", seed_x, "inner-point-y", seed_y,
               nullptr);
  gst_harness_set_src_caps_str(h, c.caps.c_str());
  for (int i = 0; i < c.frames; ++i) {
    GstBuffer* in = c.make();
    GST_BUFFER_PTS(in) = i * GST_SECOND / 30;
    const Bytes before = c.skip_bytes ? Bytes() : bytes_of(in);
    o.flow = gst_harness_push(h, in);
    if (o.flow != GST_FLOW_OK) break;
    GstBuffer* out = gst_harness_pull(h);
    if (!out) break;
    if (!c.skip_bytes) o.out = bytes_of(out);
    o.unchanged = !c.skip_bytes && o.out == before;
    o.roi = gst_buffer_get_video_region_of_interest_meta(out) != nullptr;
    o.memories = gst_buffer_n_memory(out);
    gst_buffer_unref(out);
    while (GstMessage* m = gst_bus_pop(bus)) {
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_WARNING) ++o.warnings;
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ERROR) ++o.errors;
      if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
        ++o.messages;
        const GstStructure* s = gst_message_get_structure(m);
        const char* status = gst_structure_get_string(s, "status");
        const char* reason = gst_structure_get_string(s, "reason");
        o.status = status ? status : "";
        o.reason = reason ? reason : "";
        o.cx = o.cy = o.area = NAN;
        gst_structure_get_double(s, "centroid-x", &o.cx);
        gst_structure_get_double(s, "centroid-y", &o.cy);
        gst_structure_get_double(s, "area", &o.area);
      }
      gst_message_unref(m);
    }
  }
  gst_harness_teardown(h);
  gst_bus_set_flushing(bus, TRUE);
  gst_object_unref(bus);
  return o;
}

// A refused buffer: passed through untouched, no meta, the reason said, one warning in all.
void expect_refused(const Outcome& o, const char* reason, int frames = 3) {
  EXPECT_EQ(o.flow, GST_FLOW_OK);
  EXPECT_EQ(o.status, "invalid-image");
  EXPECT_EQ(o.reason, reason);
  EXPECT_TRUE(o.unchanged) << "the buffer's bytes changed";
  EXPECT_FALSE(o.roi);
  EXPECT_EQ(o.messages, frames) << "one message per buffer";
  EXPECT_EQ(o.warnings, 1) << "one element warning, not one per buffer";
  EXPECT_EQ(o.errors, 0);
}

// The disc tracked from its plain layout: what every layout of the same picture must give.
Outcome plain(const char* format) {
  const Disc d;
  Case r{d.caps(format), [&] {
           if (std::string(format) == "GRAY8") return buffer_of(d.luma(d.width));
           const int cw = (d.width + 1) / 2;
           return buffer_of(
               joined({d.luma(d.width), d.plane(cw, true, 90, 128), d.plane(cw, true, 160, 128)}));
         }};
  r.draw = false;
  return run(r);
}

void expect_same_track(const Outcome& o, const Outcome& ref) {
  EXPECT_EQ(o.flow, GST_FLOW_OK);
  EXPECT_EQ(ref.status, "ok");
  EXPECT_EQ(o.status, ref.status);
  EXPECT_EQ(o.reason, "");
  EXPECT_DOUBLE_EQ(o.cx, ref.cx);
  EXPECT_DOUBLE_EQ(o.cy, ref.cy);
  EXPECT_DOUBLE_EQ(o.area, ref.area);
  EXPECT_EQ(o.warnings, 0);
  EXPECT_EQ(o.errors, 0);
}

// A buffer that fits, read without the overlay: the plain layout's track, its bytes unchanged.
void expect_read_as(Case c, const Outcome& ref) {
  c.draw = false;
  const Outcome o = run(c);
  expect_same_track(o, ref);
  EXPECT_TRUE(o.unchanged);
}

// The adversarial test's first case: 3 072 bytes, a meta claiming rows 4 096 bytes apart.
TEST(Buffers, MetaStrideBeyondTheMemoryIsRefused) {
  const Disc d{64, 48, 20, 20, 10};
  for (bool draw : {false, true}) {
    Case r{d.caps("GRAY8"), [&] {
             GstBuffer* b = buffer_of(d.luma(64));
             add_meta(b, GST_VIDEO_FORMAT_GRAY8, 64, 48, {0}, {4096});
             return b;
           }};
    r.draw = draw;
    expect_refused(run(r, 20, 20), "plane-outside-buffer");
  }
}

TEST(Buffers, MetaOffsetBeyondTheMemoryIsRefused) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height, {100}, {d.width});
           return b;
         }};
  expect_refused(run(r), "plane-outside-buffer");
}

TEST(Buffers, ChromaPlaneBeyondTheMemoryIsRefused) {
  const Disc d;
  const int cw = (d.width + 1) / 2, ch = (d.height + 1) / 2;
  const gsize luma = static_cast<gsize>(d.width) * d.height;
  Case r{d.caps("I420"), [&] {
           Bytes b(luma + 2 * cw * ch, 128);
           GstBuffer* buf = buffer_of(b);
           // V's offset leaves it one row short.
           add_meta(buf, GST_VIDEO_FORMAT_I420, d.width, d.height, {0, luma, luma + cw * ch + cw},
                    {d.width, cw, cw});
           return buf;
         }};
  expect_refused(run(r), "plane-outside-buffer");
}

TEST(Buffers, MetaDisagreeingWithTheCapsIsRefused) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width / 2, d.height, {0}, {d.width});
           return b;
         }};
  expect_refused(run(r), "meta-mismatch");
}

TEST(Buffers, TruncatedBufferWithoutMetaIsRefused) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           Bytes b = d.luma(d.width);
           b.resize(b.size() - 1);
           return buffer_of(b);
         }};
  expect_refused(run(r), "buffer-too-small");
  Case empty{d.caps("I420"), [] { return gst_buffer_new(); }};
  expect_refused(run(empty), "buffer-too-small");
}

// A meta whose own map function hands out less than the plane: caught after mapping.
gboolean short_map(GstVideoMeta* meta, guint plane, GstMapInfo* info, gpointer* data, gint* stride,
                   GstMapFlags flags) {
  if (!gst_buffer_map(meta->buffer, info, flags)) return FALSE;
  info->size = 100;
  *data = info->data + meta->offset[plane];
  *stride = meta->stride[plane];
  return TRUE;
}

gboolean short_unmap(GstVideoMeta* meta, guint, GstMapInfo* info) {
  gst_buffer_unmap(meta->buffer, info);
  return TRUE;
}

TEST(Buffers, PlaneLargerThanItsMappingIsRefused) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height, {0}, {d.width});
           GstVideoMeta* meta = gst_buffer_get_video_meta(b);
           meta->map = short_map;
           meta->unmap = short_unmap;
           return b;
         }};
  expect_refused(run(r), "plane-outside-mapping");
}

// Stride 0 repeats one row on every row: a picture no camera makes, so a lie about the layout.
TEST(Buffers, ZeroStrideIsRefusedUnlessTheFrameHasOneRow) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(Bytes(d.width, 40));
           add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height, {0}, {0});
           return b;
         }};
  expect_refused(run(r), "rows-overlap");

  const Disc row{96, 1, 48, 0, 0};
  Case one{row.caps("GRAY8"), [&] {
             GstBuffer* b = buffer_of(Bytes(row.width, 40));
             add_meta(b, GST_VIDEO_FORMAT_GRAY8, row.width, 1, {0}, {0});
             return b;
           }};
  const Outcome o = run(one, 48, 0);
  EXPECT_NE(o.status, "invalid-image");
  EXPECT_EQ(o.warnings, 0);
}

TEST(Buffers, RowsCloserThanTheirWidthAreRefused) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height, {0}, {d.width - 1});
           return b;
         }};
  expect_refused(run(r), "rows-overlap");
}

// The adversarial test's second case: the luma plane split across two memory blocks.
TEST(Buffers, PlaneSplitAcrossMemoryBlocksIsTracked) {
  const Disc d;
  const Outcome ref = plain("GRAY8");
  for (std::size_t at : {std::size_t{1}, std::size_t{1000}, std::size_t{96 * 30 + 7}}) {
    for (bool meta : {true, false}) {
      Case r{d.caps("GRAY8"), [&] {
               GstBuffer* b = split_buffer(d.luma(d.width), at);
               if (meta) add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height, {0}, {d.width});
               return b;
             }};
      SCOPED_TRACE("cut at " + std::to_string(at) + (meta ? " with a meta" : " without a meta"));
      expect_read_as(r, ref);
    }
  }
}

// Planes each in a memory of their own (as some decoders allocate): read in place.
TEST(Buffers, PlanesInMemoriesOfTheirOwnAreTracked) {
  const Disc d;
  const Outcome ref = plain("I420");
  const int cw = (d.width + 1) / 2, ch = (d.height + 1) / 2;
  Case r{d.caps("I420"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           b = gst_buffer_append(b, buffer_of(d.plane(cw, true, 90, 128)));
           b = gst_buffer_append(b, buffer_of(d.plane(cw, true, 160, 128)));
           const gsize luma = static_cast<gsize>(d.width) * d.height;
           add_meta(b, GST_VIDEO_FORMAT_I420, d.width, d.height, {0, luma, luma + cw * ch},
                    {d.width, cw, cw});
           return b;
         }};
  r.draw = false;
  const Outcome o = run(r);
  expect_same_track(o, ref);
  EXPECT_EQ(o.memories, 3u) << "planes that each fit their block are not merged (a copy)";
}

// U and V planes with strides of their own (the library reads chroma with one stride): found by
// fuzzing, an overflow past the V plane under ASan.
TEST(Buffers, ChromaPlanesWithDifferentStridesAreTracked) {
  const Disc d;
  const Outcome ref = plain("I420");
  const int cw = (d.width + 1) / 2, ch = (d.height + 1) / 2, wide = cw + 20;
  Case r{d.caps("I420"), [&] {
           GstBuffer* buf = buffer_of(joined(
               {d.luma(d.width), d.plane(wide, true, 90, 128), d.plane(cw, true, 160, 128)}));
           const gsize luma = static_cast<gsize>(d.width) * d.height;
           add_meta(buf, GST_VIDEO_FORMAT_I420, d.width, d.height,
                    {0, luma, luma + static_cast<gsize>(wide) * ch}, {d.width, wide, cw});
           return buf;
         }};
  expect_read_as(r, ref);
}

// Bottom-up rows (negative strides) are supported: the same picture, the same track, and the
// overlay drawn on the same pixels.
TEST(Buffers, BottomUpRowsAreTrackedAsTopDownOnes) {
  const Disc d;
  const Outcome ref = plain("GRAY8");
  const auto bottom_up = [&] {
    GstBuffer* b = buffer_of(upside_down(d.luma(d.width), d.height));
    add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height,
             {static_cast<gsize>(d.width) * (d.height - 1)}, {-d.width});
    return b;
  };
  Case r{d.caps("GRAY8"), bottom_up};
  expect_read_as(r, ref);

  // With the overlay: the bottom-up output, turned over, is the top-down output.
  Case top_down{d.caps("GRAY8"), [&] { return buffer_of(d.luma(d.width)); }};
  const Outcome drawn_ref = run(top_down);
  r.draw = true;
  const Outcome drawn = run(r);
  EXPECT_FALSE(drawn_ref.unchanged) << "the overlay draws";
  EXPECT_EQ(upside_down(drawn.out, d.height), drawn_ref.out);
}

TEST(Buffers, BottomUpPlanarYuvIsTrackedAsTopDown) {
  const Disc d;
  const Outcome ref = plain("I420");
  const int cw = (d.width + 1) / 2, ch = (d.height + 1) / 2;
  Case r{d.caps("I420"), [&] {
           GstBuffer* buf = buffer_of(joined({upside_down(d.luma(d.width), d.height),
                                              upside_down(d.plane(cw, true, 90, 128), ch),
                                              upside_down(d.plane(cw, true, 160, 128), ch)}));
           const gsize luma = static_cast<gsize>(d.width) * d.height, chroma = cw * ch;
           add_meta(buf, GST_VIDEO_FORMAT_I420, d.width, d.height,
                    {luma - d.width, luma + chroma - cw, luma + 2 * chroma - cw},
                    {-d.width, -cw, -cw});
           return buf;
         }};
  expect_read_as(r, ref);
}

// A bottom-up plane whose first row (at the offset) fits but whose last row would be before the
// buffer's start.
TEST(Buffers, BottomUpRowsBeforeTheBufferAreRefused) {
  const Disc d;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height,
                    {static_cast<gsize>(d.width) * 10}, {-d.width});
           return b;
         }};
  expect_refused(run(r), "plane-outside-buffer");
}

// The inner point given before a buffer that is not read still starts the track on the next one
// (without it, auto acquisition would search: the disc does not move).
TEST(Buffers, ASeedWaitsForTheNextReadableBuffer) {
  const Disc d;
  int pushed = 0;
  Case r{d.caps("GRAY8"), [&] {
           GstBuffer* b = buffer_of(d.luma(d.width));
           if (pushed++ == 0) add_meta(b, GST_VIDEO_FORMAT_GRAY8, d.width, d.height, {0}, {0});
           return b;
         }};
  r.frames = 2;
  r.draw = false;
  const Outcome o = run(r);
  EXPECT_EQ(o.status, "ok");
  EXPECT_EQ(o.warnings, 1);
  EXPECT_EQ(o.messages, 2);
}

// Caps of 65536 × 32769 GRAY8 (2^31 + 65536 pixels, which GStreamer accepts): refused before any
// pixel is read. The memory is a read-only, never-touched mapping, so a read costs nothing and a
// write would crash.
TEST(Buffers, FramesAboveTheSizeLimitAreRefused) {
  const int w = 65536, h = 32769;
  GstVideoInfo info;
  ASSERT_TRUE(gst_video_info_set_format(&info, GST_VIDEO_FORMAT_GRAY8, w, h));
  const gsize size = GST_VIDEO_INFO_SIZE(&info);
  ASSERT_GT(size, gsize{G_MAXINT});
  const std::string caps = "video/x-raw,format=GRAY8,width=" + std::to_string(w) +
                           ",height=" + std::to_string(h) + ",framerate=30/1";
  Case r{caps, [&] {
           struct Mapping {
             void* data;
             gsize size;
           };
           void* p =
               mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
           EXPECT_NE(p, MAP_FAILED);
           return gst_buffer_new_wrapped_full(GST_MEMORY_FLAG_READONLY, p, size, 0, size,
                                              new Mapping{p, size}, [](gpointer q) {
                                                auto* m = static_cast<Mapping*>(q);
                                                munmap(m->data, m->size);
                                                delete m;
                                              });
         }};
  r.skip_bytes = true;
  const Outcome o = run(r, 100, 100);
  EXPECT_EQ(o.flow, GST_FLOW_OK);
  EXPECT_EQ(o.status, "invalid-image");
  EXPECT_EQ(o.reason, "too-large");
  EXPECT_FALSE(o.roi);
  EXPECT_EQ(o.warnings, 1);
  EXPECT_EQ(o.errors, 0);

  // The same caps and a small buffer: too small before too large.
  Case small{caps, [] { return gst_buffer_new_allocate(nullptr, 4096, nullptr); }};
  expect_refused(run(small), "buffer-too-small");
}

}  // namespace
