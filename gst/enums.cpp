// The element's enum and flags types, as gst-inspect-1.0 shows them: one value per row of a name
// table (include/projtrack/names.hpp for the library's enums; updates_table.def and
// draw_flags_table.def for the element's own). Each is registered, and marked as the plugin's API,
// on its first use (the property table's GParamSpecs use each one); a function-local static makes
// that thread-safe.
#include <gst/gst.h>

#include <cstddef>

#include "enum_types.h"
#include "projtrack/names.hpp"
#include "settings.hpp"

namespace {

using projtrack::NameRow;

// The GEnumValues (or GFlagsValues) of a table, zero-terminated. GLib keeps the pointer for the
// life of the process: the array is never freed.
template <class Value, class E, std::size_t N>
const Value* values_of(const NameRow<E> (&rows)[N]) {
  auto* values = new Value[N + 1]();
  for (std::size_t i = 0; i < N; ++i)
    values[i] = {static_cast<decltype(Value::value)>(rows[i].value), rows[i].description,
                 rows[i].nick};
  return values;
}

// Registered, and marked as the plugin's API so that gst-inspect-1.0 and the docs list its values.
GType plugin_api(GType type) {
  gst_type_mark_as_plugin_api(type, static_cast<GstPluginAPIFlags>(0));
  return type;
}

template <class E, std::size_t N>
GType register_enum(const char* name, const NameRow<E> (&rows)[N]) {
  return plugin_api(g_enum_register_static(name, values_of<GEnumValue>(rows)));
}

constexpr NameRow<projtrack::gst::Updates> kUpdatesNames[] = {
#define PROJTRACK_NAME(value, nick, description) \
  {projtrack::gst::Updates::value, nick, description},
#include "updates_table.def"
#undef PROJTRACK_NAME
};

constexpr NameRow<unsigned> kDrawFlagNames[] = {
#define PROJTRACK_NAME(value, nick, description) {projtrack::gst::value, nick, description},
#include "draw_flags_table.def"
#undef PROJTRACK_NAME
};

}  // namespace

GType gst_projtrack_method_get_type(void) {
  static const GType type = register_enum("GstProjtrackMethod", projtrack::kMethodNames);
  return type;
}

GType gst_projtrack_edge_detector_get_type(void) {
  static const GType type =
      register_enum("GstProjtrackEdgeDetector", projtrack::kEdgeDetectorNames);
  return type;
}

GType gst_projtrack_acquisition_get_type(void) {
  static const GType type = register_enum("GstProjtrackAcquisition", projtrack::kAcquisitionNames);
  return type;
}

GType gst_projtrack_object_model_get_type(void) {
  static const GType type = register_enum("GstProjtrackObjectModel", projtrack::kObjectModelNames);
  return type;
}

GType gst_projtrack_updates_get_type(void) {
  static const GType type = register_enum("GstProjtrackUpdates", kUpdatesNames);
  return type;
}

GType gst_projtrack_draw_flags_get_type(void) {
  static const GType type = plugin_api(
      g_flags_register_static("GstProjtrackDrawFlags", values_of<GFlagsValue>(kDrawFlagNames)));
  return type;
}
