// What YUY2's luma gather costs against the whole element's cost per frame, side by side in one
// run, at 640×480 and 1920×1080 (docs/element.md, "Formats"): a generated sphere moving over 60
// frames, tracked from a seed, pushed as YUY2 and as I420 (where luma is read in place) through
// projtrack in GstHarness; the gather timed alone on the same YUY2 frames, with the library's
// gather_component() and with the loop of a variable pixel stride it replaced, beside a GRAY8
// frame copy. Every frame is a buffer of its own, so the gathers read memory as the element does
// (not a frame left in the cache). Medians over 5 rounds of frames 5-59. Built with the tools
// option (tools/meson.build) beside the plugin, in a build folder made by ./run build:
//
//   meson configure build -Dtools=enabled && meson compile -C build
//   GST_PLUGIN_PATH=$PWD/build/gst build/tools/packed_yuv_cost
#include <gst/check/gstharness.h>
#include <gst/gst.h>
#include <gst/video/video.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "projtrack/color_conversion.hpp"
#include "scene.hpp"
#include "sequence.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double us(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

std::string caps(const char* format, int w, int h) {
  return "video/x-raw,format=" + std::string(format) + ",width=" + std::to_string(w) +
         ",height=" + std::to_string(h) + ",framerate=30/1";
}

GstBuffer* convert(GstBuffer* gray, const char* to, int w, int h) {
  GstHarness* c = gst_harness_new("videoconvert");
  gst_harness_set_src_caps_str(c, caps("GRAY8", w, h).c_str());
  gst_harness_set_sink_caps_str(c, caps(to, w, h).c_str());
  GstBuffer* out = gst_harness_push_and_pull(c, gray);
  gst_harness_teardown(c);
  return out;
}

// The gather before: a pixel stride known only at run time (not vectorised; noipa keeps the
// compiler from specialising it for the constant 2 passed here).
__attribute__((noipa)) void variable_stride_gather(const std::uint8_t* first, int pixel_stride,
                                                   std::ptrdiff_t row_stride, int width, int height,
                                                   std::uint8_t* out, std::ptrdiff_t out_stride) {
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* in = first + y * row_stride;
    std::uint8_t* o = out + y * out_stride;
    for (int x = 0; x < width; ++x) o[x] = in[static_cast<std::ptrdiff_t>(x) * pixel_stride];
  }
}

// The element's time per frame (processing-time, µs) on `frames` in `format`, from frame 5 on.
void run_element(const std::vector<GstBuffer*>& frames, const char* format, int w, int h,
                 projtrack::Point2i seed, std::vector<double>& times) {
  GstHarness* harness = gst_harness_new("projtrack");
  GstBus* bus = gst_bus_new();
  gst_element_set_bus(harness->element, bus);
  gst_harness_set_src_caps_str(harness, caps(format, w, h).c_str());
  g_signal_emit_by_name(harness->element, "track-point", seed.x, seed.y);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    GstBuffer* b = gst_buffer_ref(frames[i]);
    GST_BUFFER_PTS(b) = i * GST_SECOND / 30;
    gst_harness_push(harness, b);
    gst_buffer_unref(gst_harness_pull(harness));
    GstMessage* m = gst_bus_pop_filtered(bus, GST_MESSAGE_ELEMENT);
    const GstStructure* s = gst_message_get_structure(m);
    guint64 ns = 0;
    gst_structure_get_uint64(s, "processing-time", &ns);
    if (i >= 5) times.push_back(ns / 1000.0);
    if (i + 1 == frames.size() && g_strcmp0(gst_structure_get_string(s, "status"), "ok"))
      std::fprintf(stderr, "%s %dx%d: not tracked at the end\n", format, w, h);
    gst_message_unref(m);
  }
  gst_harness_teardown(harness);
  gst_bus_set_flushing(bus, TRUE);
  gst_object_unref(bus);
}

}  // namespace

int main(int argc, char** argv) {
  gst_init(&argc, &argv);
  const int n = 60, rounds = 5;
  std::printf(
      "| frame | gather (library) | gather (variable stride) | GRAY8 copy | element, YUY2 "
      "| element, I420 | gather ÷ element (YUY2) |\n|---|---|---|---|---|---|---|\n");
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}}) {
    const double k = h / 480.0;
    std::vector<GstBuffer*> gray, yuy2, i420;
    projtrack::Point2i seed;
    for (int i = 0; i < n; ++i) {
      auto spec = projtrack::synthetic::frame_at(projtrack::synthetic::Object::Sphere,
                                                 k * (260 + 2 * i), k * 240, i, 1.0);
      spec.width = w;
      spec.height = h;
      const projtrack::synthetic::Scene s = projtrack::synthetic::make_scene(spec, {});
      if (i == 0) seed = {static_cast<int>(s.true_centroid.x), static_cast<int>(s.true_centroid.y)};
      gray.push_back(gst_buffer_new_memdup(s.image.data, s.image.total()));
      yuy2.push_back(convert(gst_buffer_ref(gray.back()), "YUY2", w, h));
      i420.push_back(convert(gst_buffer_ref(gray.back()), "I420", w, h));
    }
    std::vector<double> library, variable, copy, element_yuy2, element_i420;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * h);
    const int stride = GST_ROUND_UP_4(2 * w);
    for (int r = 0; r < rounds; ++r) {
      run_element(yuy2, "YUY2", w, h, seed, element_yuy2);
      run_element(i420, "I420", w, h, seed, element_i420);
      for (int i = 5; i < n; ++i) {
        const auto timed = [&](GstBuffer* b, auto&& f, std::vector<double>& times) {
          GstMapInfo map;
          gst_buffer_map(b, &map, GST_MAP_READ);
          const auto t0 = Clock::now();
          f(map.data);
          times.push_back(us(Clock::now() - t0));
          gst_buffer_unmap(b, &map);
        };
        // Each on frames the other did not just read.
        timed(
            yuy2[i],
            [&](const guint8* d) {
              projtrack::gather_component(d, 2, stride, w, h, out.data(), w);
            },
            library);
        timed(
            yuy2[(i + n / 2) % n],
            [&](const guint8* d) { variable_stride_gather(d, 2, stride, w, h, out.data(), w); },
            variable);
        timed(
            gray[i], [&](const guint8* d) { std::memcpy(out.data(), d, out.size()); }, copy);
      }
    }
    std::printf("| %d×%d | %.0f µs | %.0f µs | %.0f µs | %.0f µs | %.0f µs | %.0f %% |\n", w, h,
                median(library), median(variable), median(copy), median(element_yuy2),
                median(element_i420), 100 * median(library) / median(element_yuy2));
    for (auto* frames : {&gray, &yuy2, &i420})
      for (GstBuffer* b : *frames) gst_buffer_unref(b);
  }
  return 0;
}
