#include "element_harness.hpp"

namespace projtrack::bench {

ElementHarness::ElementHarness(const std::string& launch, const std::string& caps,
                               bool collect_messages) {
  h_ = gst_harness_new_parse(launch.c_str());
  gst_harness_set_src_caps_str(h_, caps.c_str());
  // GstHarness gives the element no bus: give it one, to read (or drop) what it posts.
  bus_ = gst_bus_new();
  if (!collect_messages) gst_bus_set_flushing(bus_, TRUE);
  gst_element_set_bus(h_->element, bus_);
}

ElementHarness::~ElementHarness() {
  for (GstMessage* m : take_messages()) gst_message_unref(m);
  gst_element_set_bus(h_->element, nullptr);
  gst_object_unref(bus_);
  gst_harness_teardown(h_);
}

GstBuffer* ElementHarness::push_pull(GstBuffer* frame) {
  if (gst_harness_push(h_, gst_buffer_ref(frame)) != GST_FLOW_OK) return nullptr;
  return gst_harness_pull(h_);
}

bool ElementHarness::run(GstBuffer* frame) {
  GstBuffer* out = push_pull(frame);
  if (!out) return false;
  gst_buffer_unref(out);
  return true;
}

std::vector<GstMessage*> ElementHarness::take_messages() {
  std::vector<GstMessage*> out;
  while (GstMessage* m = gst_bus_pop_filtered(bus_, GST_MESSAGE_ELEMENT)) out.push_back(m);
  return out;
}

std::string raw_caps(const char* format, int width, int height, int fps_n, int fps_d) {
  return std::string("video/x-raw,format=") + format + ",width=" + std::to_string(width) +
         ",height=" + std::to_string(height) + ",framerate=" + std::to_string(fps_n) + "/" +
         std::to_string(fps_d);
}

}  // namespace projtrack::bench
