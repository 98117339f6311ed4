// Section 9: gst_element_set_state(NULL) on a pipeline whose element is in a frame that would take
// minutes (no work limit: max-work=0; a million rays per cast on a uniform 1080p frame, so every
// ray crosses the frame): the time set_state takes to return, and the status the frame ended with.
#include <gst/gst.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "harness.hpp"
#include "output.hpp"
#include "race.hpp"
#include "sections.hpp"

namespace projtrack::bench {
namespace {

struct InterruptTrial {
  double latency_us = NAN;
  std::string status;
};

InterruptTrial interrupt_trial(const Clip& c, int wait_ms) {
  InterruptTrial trial;
  const std::string launch =
      "appsrc name=src format=time caps=\"" + caps_of("I420", c) +
      "\" ! projtrack name=t object-model=edges method=recursive-ray-casting rays=1024 "
      "recursion=2 max-iterations=1000 convergence=0 max-work=0 acquisition=manual "
      "inner-point-x=" +
      std::to_string(c.width / 2) + " inner-point-y=" + std::to_string(c.height / 2) +
      " ! fakesink sync=false";
  GstElement* p = gst_parse_launch(launch.c_str(), nullptr);
  if (!p) return trial;
  GstElement* src = gst_bin_get_by_name(GST_BIN(p), "src");
  GstElement* t = gst_bin_get_by_name(GST_BIN(p), "t");
  struct Shared {
    std::mutex m;
    std::condition_variable cv;
    bool entered = false;
    std::string status;
  } shared;
  // The buffer is in the element's chain function (its stream lock held) when the probe runs.
  GstPad* sink = gst_element_get_static_pad(t, "sink");
  gst_pad_add_probe(
      sink, GST_PAD_PROBE_TYPE_BUFFER,
      [](GstPad*, GstPadProbeInfo*, gpointer data) {
        auto* sh = static_cast<Shared*>(data);
        std::lock_guard<std::mutex> lock(sh->m);
        sh->entered = true;
        sh->cv.notify_all();
        return GST_PAD_PROBE_OK;
      },
      &shared, nullptr);
  gst_object_unref(sink);
  GstBus* bus = gst_element_get_bus(p);
  gst_bus_set_sync_handler(
      bus,
      [](GstBus*, GstMessage* m, gpointer data) {
        if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
          auto* sh = static_cast<Shared*>(data);
          const char* s = gst_structure_get_string(gst_message_get_structure(m), "status");
          std::lock_guard<std::mutex> lock(sh->m);
          sh->status = s ? s : "";
        }
        gst_message_unref(m);
        return GST_BUS_DROP;
      },
      &shared, nullptr);
  gst_object_unref(bus);
  gst_element_set_state(p, GST_STATE_PLAYING);
  GstFlowReturn ret;
  g_signal_emit_by_name(src, "push-buffer", c.i420[0], &ret);
  {
    std::unique_lock<std::mutex> lock(shared.m);
    shared.cv.wait_for(lock, std::chrono::seconds(30), [&] { return shared.entered; });
  }
  // Well inside the frame (which would take minutes), then stop.
  std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
  const auto t0 = Clock::now();
  gst_element_set_state(p, GST_STATE_NULL);
  trial.latency_us = 1e6 * seconds_since(t0);
  {
    std::lock_guard<std::mutex> lock(shared.m);
    trial.status = shared.entered ? shared.status : "not started";
  }
  gst_object_unref(t);
  gst_object_unref(src);
  gst_object_unref(p);
  return trial;
}

}  // namespace

void interrupt_latency(int trials) {
  auto c = std::make_unique<Clip>();
  c->name = "uniform";
  c->width = 1920;
  c->height = 1080;
  add_frame(*c, cv::Mat(1080, 1920, CV_8U, cv::Scalar(128)));
  std::vector<double> us;
  int interrupted = 0;
  for (int i = 0; i < trials; ++i) {
    const InterruptTrial t = interrupt_trial(*c, 50 + 25 * (i % 4));
    us.push_back(t.latency_us);
    interrupted += t.status == "interrupted";
  }
  const std::string what = "set_state(NULL) during a heavy frame";
  row("interrupt", c.get(), what, "latency_us_median", median(us));
  row("interrupt", c.get(), what, "latency_us_max", *std::max_element(us.begin(), us.end()));
  row("interrupt", c.get(), what, "trials", trials);
  row("interrupt", c.get(), what, "frames_interrupted", interrupted);
}

}  // namespace projtrack::bench
