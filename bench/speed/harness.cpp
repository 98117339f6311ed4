// The element in a GstHarness: see harness.hpp.
#include "harness.hpp"

namespace projtrack::bench {

Harness::Harness(const std::string& launch, const std::string& caps, bool keep_status) {
  h_ = gst_harness_new_parse(launch.c_str());
  gst_harness_set_src_caps_str(h_, caps.c_str());
  bus_ = gst_bus_new();
  if (keep_status)
    gst_bus_set_sync_handler(bus_, status_of, &status_, nullptr);
  else
    gst_bus_set_flushing(bus_, TRUE);
  gst_element_set_bus(h_->element, bus_);
}

Harness::~Harness() {
  gst_element_set_bus(h_->element, nullptr);
  gst_object_unref(bus_);
  gst_harness_teardown(h_);
}

void Harness::reset() {
  GstIterator* it = gst_bin_iterate_all_by_element_factory_name(GST_BIN(h_->element), "projtrack");
  GValue v = G_VALUE_INIT;
  if (gst_iterator_next(it, &v) == GST_ITERATOR_OK) {
    g_signal_emit_by_name(g_value_get_object(&v), "reset");
    g_value_unset(&v);
  }
  gst_iterator_free(it);
}

GstBusSyncReply Harness::status_of(GstBus*, GstMessage* m, gpointer status) {
  if (GST_MESSAGE_TYPE(m) == GST_MESSAGE_ELEMENT && gst_message_has_name(m, "projtrack")) {
    const char* s = gst_structure_get_string(gst_message_get_structure(m), "status");
    *static_cast<std::string*>(status) = s ? s : "";
  }
  gst_message_unref(m);
  return GST_BUS_DROP;
}

std::string caps_of(const char* format, const Clip& c) {
  return std::string("video/x-raw,format=") + format + ",width=" + std::to_string(c.width) +
         ",height=" + std::to_string(c.height) + ",framerate=30/1";
}

std::string projtrack_launch(const std::string& method, const Clip& c) {
  if (c.name == "real") return "projtrack method=" + method + " acquisition=auto";
  return "projtrack method=" + method +
         " acquisition=manual inner-point-x=" + std::to_string(c.seeds[0].x) +
         " inner-point-y=" + std::to_string(c.seeds[0].y);
}

}  // namespace projtrack::bench
