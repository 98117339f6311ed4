// The element (or any launch line) in a GstHarness: push a frame, pull it back. Its messages go
// to a bus of its own, flushing, or kept for their status.
#pragma once

#include <gst/check/gstharness.h>
#include <gst/gst.h>

#include <string>

#include "clip.hpp"

namespace projtrack::bench {

class Harness {
 public:
  // `keep_status`: the status of the element's last message is kept (status()); else messages
  // are made and posted, then dropped.
  Harness(const std::string& launch, const std::string& caps, bool keep_status = false);
  ~Harness();
  Harness(const Harness&) = delete;
  Harness& operator=(const Harness&) = delete;
  // Pushes one frame and takes it back out; false if the element refused it. Inline: it is what
  // every contender's time is measured around.
  bool run(GstBuffer* frame) {
    if (gst_harness_push(h_, gst_buffer_ref(frame)) != GST_FLOW_OK) return false;
    GstBuffer* out = gst_harness_pull(h_);
    if (!out) return false;
    gst_buffer_unref(out);
    return true;
  }
  GstElement* element() { return h_->element; }
  // Forgets the track (the element's reset signal), as a new stream would start.
  void reset();
  const std::string& status() const { return status_; }

 private:
  static GstBusSyncReply status_of(GstBus*, GstMessage* m, gpointer status);
  GstHarness* h_;
  GstBus* bus_;
  std::string status_;
};

// The caps of `c`'s frames in `format` (I420 or RGB), 30 fps.
std::string caps_of(const char* format, const Clip& c);

// projtrack with `method`: seeded at the clip's first seed, or on the real clip (whose object is
// unknown) finding one by itself.
std::string projtrack_launch(const std::string& method, const Clip& c);

}  // namespace projtrack::bench
