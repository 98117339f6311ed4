// The element's properties, made from the property table (property_table.def): their ids, their
// GParamSpecs, and set_property/get_property, which hold the object lock around every access.
#pragma once

#include <gst/gst.h>

namespace projtrack::gst {

enum PropertyId : guint {
  PROP_0,
#define PROJTRACK_PROPERTY(id, ...) PROP_##id,
#include "property_table.def"
#undef PROJTRACK_PROPERTY
  N_PROPERTIES
};

// Builds every row's GParamSpec and installs them on the element's class.
void install_properties(GObjectClass* klass);

void set_property(GObject* object, guint prop_id, const GValue* value, GParamSpec* pspec);
void get_property(GObject* object, guint prop_id, GValue* value, GParamSpec* pspec);

}  // namespace projtrack::gst
