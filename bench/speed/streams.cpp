// Section 6: concurrent 30 fps streams in one process, each a real pipeline with its own
// streaming thread (appsrc ! projtrack ! fakesink), fed as fast as they take frames. What counts
// is a frame tracked: its projtrack message arrived with a status that carries features. Pushes
// the source refused, streams that did not finish in time and errors are counted too.
#include <gst/gst.h>

#include <atomic>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <unordered_set>
#include <vector>

#include "harness.hpp"
#include "output.hpp"
#include "projtrack/tracker.hpp"
#include "race.hpp"
#include "sections.hpp"

namespace projtrack::bench {
namespace {

struct StreamsResult {
  long pushed = 0, refused = 0;    // buffers offered, and those the source did not take
  long messages = 0, tracked = 0;  // projtrack messages, and those with a tracking status
  int timeouts = 0, errors = 0;    // streams with no end of stream in time, or an error
  double seconds = 0;
};

GstBusSyncReply count_message(GstBus*, GstMessage* m, gpointer data) {
  if (GST_MESSAGE_TYPE(m) != GST_MESSAGE_ELEMENT || !gst_message_has_name(m, "projtrack"))
    return GST_BUS_PASS;
  static const std::unordered_set<std::string> tracking = [] {
    std::unordered_set<std::string> names;
    for (int s = 0; s <= static_cast<int>(kLastTrackStatus); ++s)
      if (has_features(static_cast<TrackStatus>(s)))
        names.insert(std::string(status_name(static_cast<TrackStatus>(s))));
    return names;
  }();
  auto* counts = static_cast<std::atomic<long>*>(data);  // messages, tracked
  const char* status = gst_structure_get_string(gst_message_get_structure(m), "status");
  ++counts[0];
  if (status && tracking.count(status)) ++counts[1];
  gst_message_unref(m);
  return GST_BUS_DROP;  // counted where it was posted; nothing piles up on the bus
}

StreamsResult run_streams(const Clip& clip, int streams, int frames_each, int timeout_s) {
  struct Stream {
    GstElement* pipeline;
    GstElement* src;
    std::atomic<long> counts[2] = {0, 0};
    long refused = 0;
  };
  StreamsResult res;
  std::vector<std::unique_ptr<Stream>> ss;
  for (int s = 0; s < streams; ++s) {
    const std::string launch = "appsrc name=src format=time block=true max-bytes=2000000 caps=\"" +
                               caps_of("I420", clip) + "\" ! " +
                               projtrack_launch(kDefaultMethod, clip) + " ! fakesink sync=false";
    GError* err = nullptr;
    GstElement* p = gst_parse_launch(launch.c_str(), &err);
    if (!p) {
      std::fprintf(stderr, "projtrack-speed: %s\n", err ? err->message : "parse failed");
      g_clear_error(&err);
      ++res.errors;
      continue;
    }
    auto stream = std::make_unique<Stream>();
    stream->pipeline = p;
    stream->src = gst_bin_get_by_name(GST_BIN(p), "src");
    GstBus* bus = gst_element_get_bus(p);
    gst_bus_set_sync_handler(bus, count_message, stream->counts, nullptr);
    gst_object_unref(bus);
    gst_element_set_state(p, GST_STATE_PLAYING);
    ss.push_back(std::move(stream));
  }
  const auto t0 = Clock::now();
  std::vector<std::thread> feeders;
  for (auto& s : ss) {
    feeders.emplace_back([&clip, s = s.get(), frames_each] {
      const std::size_t n = clip.i420.size();
      for (int i = 0; i < frames_each; ++i) {
        GstBuffer* b = gst_buffer_copy(clip.i420[static_cast<std::size_t>(i) % n]);  // shallow
        GST_BUFFER_PTS(b) = gst_util_uint64_scale(i, GST_SECOND, 30);
        GST_BUFFER_DURATION(b) = GST_SECOND / 30;
        GstFlowReturn ret = GST_FLOW_ERROR;
        g_signal_emit_by_name(s->src, "push-buffer", b, &ret);
        gst_buffer_unref(b);
        s->refused += ret != GST_FLOW_OK;
      }
      GstFlowReturn ret;
      g_signal_emit_by_name(s->src, "end-of-stream", &ret);
    });
  }
  for (std::thread& f : feeders) f.join();
  for (auto& s : ss) {
    GstBus* bus = gst_element_get_bus(s->pipeline);
    GstMessage* m = gst_bus_timed_pop_filtered(
        bus, timeout_s * GST_SECOND,
        static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
    if (!m) {
      ++res.timeouts;
    } else {
      res.errors += GST_MESSAGE_TYPE(m) == GST_MESSAGE_ERROR;
      gst_message_unref(m);
    }
    gst_object_unref(bus);
  }
  res.seconds = seconds_since(t0);
  for (auto& s : ss) {
    gst_element_set_state(s->pipeline, GST_STATE_NULL);
    res.pushed += frames_each;
    res.refused += s->refused;
    res.messages += s->counts[0];
    res.tracked += s->counts[1];
    gst_object_unref(s->src);
    gst_object_unref(s->pipeline);
  }
  return res;
}

}  // namespace

void streams_rows(const Clip& clip, int streams, int frames_each) {
  constexpr int kTimeoutSeconds = 120;
  const StreamsResult r = run_streams(clip, streams, frames_each, kTimeoutSeconds);
  const std::string what = std::to_string(streams) + (streams == 1 ? " stream" : " streams");
  row("streams", &clip, what, "streams", streams);
  row("streams", &clip, what, "fps", r.tracked / r.seconds);  // frames tracked per second
  row("streams", &clip, what, "frames_pushed", static_cast<double>(r.pushed));
  row("streams", &clip, what, "pushes_refused", static_cast<double>(r.refused));
  row("streams", &clip, what, "messages", static_cast<double>(r.messages));
  row("streams", &clip, what, "frames_tracked", static_cast<double>(r.tracked));
  row("streams", &clip, what, "timeouts", r.timeouts);
  row("streams", &clip, what, "timeout_s", kTimeoutSeconds);
  row("streams", &clip, what, "errors", r.errors);
  row("streams", &clip, what, "seconds", r.seconds);
}

}  // namespace projtrack::bench
