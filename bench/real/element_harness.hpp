// One GStreamer element in a GstHarness, as the benchmarks drive it: a frame pushed in, the
// frame pulled out, and the element messages it posted on the way.
#pragma once

#include <gst/check/gstharness.h>
#include <gst/gst.h>

#include <string>
#include <vector>

namespace projtrack::bench {

class ElementHarness {
 public:
  // `launch` is a gst-launch description of one element (or a chain); `caps` the input's.
  // With `collect_messages` false, messages are made and posted, then dropped.
  ElementHarness(const std::string& launch, const std::string& caps, bool collect_messages);
  ~ElementHarness();
  ElementHarness(const ElementHarness&) = delete;
  ElementHarness& operator=(const ElementHarness&) = delete;

  // Pushes `frame` (a reference is taken) and returns the buffer that came out (the caller owns
  // it), or null if the element refused the frame.
  GstBuffer* push_pull(GstBuffer* frame);
  // Pushes and pulls, dropping the output; false if the element refused the frame.
  bool run(GstBuffer* frame);
  // The element messages posted since the last call (the caller unrefs them).
  std::vector<GstMessage*> take_messages();
  GstElement* element() { return h_->element; }

 private:
  GstHarness* h_;
  GstBus* bus_;
};

std::string raw_caps(const char* format, int width, int height, int fps_n = 30, int fps_d = 1);

}  // namespace projtrack::bench
