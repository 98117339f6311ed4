// The property table (property_table.def) expanded three times: into the GParamSpecs, into
// set_property and into get_property. Every access happens under the object lock, so that the
// streaming thread copies whole settings.
#include "properties.hpp"

#include <string>
#include <vector>

#include "element.hpp"
#include "enum_types.h"
#include "objects.hpp"
#include "property_types.hpp"
#include "seeds.hpp"

namespace projtrack::gst {

namespace {

GParamSpec* specs[N_PROPERTIES];

// A property's blurb: `what` it does, after the methods it tunes (those of the table of methods
// for which `tunes` holds), as "grid-filling and gap-tolerant-filling: what". The list comes from
// the table's traits, so that a new method keeps the blurbs true. Interned: the blurb lives as long
// as the process, as G_PARAM_STATIC_STRINGS wants.
template <class Tunes>
const char* blurb_of_methods(Tunes tunes, const char* what) {
  std::vector<const char*> nicks;
  for (const MethodInfo& m : kMethods)
    if (tunes(m)) nicks.push_back(m.nick);
  std::string blurb;
  for (std::size_t i = 0; i < nicks.size(); ++i)
    blurb += std::string(i == 0 ? "" : i + 1 == nicks.size() ? " and " : ", ") + nicks[i];
  return g_intern_string((blurb + ": " + what).c_str());
}

// The methods that read the parameter of `bit` (the table's `reads` column).
auto reading(ReadsParam bit) {
  return [bit](const MethodInfo& m) { return (m.reads & bit) != 0; };
}

bool iterates(const MethodInfo& m) { return m.iterative; }

// The method's blurb names the default method (interned, as above).
const char* method_blurb() {
  return g_intern_string((std::string("The estimator: rays cast from the inner point, or a fill "
                                      "(default ") +
                          nick_of(ElementSettings{}.method) + ")")
                             .c_str());
}

}  // namespace

void install_properties(GObjectClass* klass) {
  const ElementSettings defaults;
#define PROJTRACK_PROPERTY(id, name, nick, type, range, def, flags, access, blurb) \
  specs[PROP_##id] = param_spec(name, nick, blurb, type::Range range, def,         \
                                static_cast<GParamFlags>((flags) | G_PARAM_STATIC_STRINGS));
#include "property_table.def"
#undef PROJTRACK_PROPERTY
  g_object_class_install_properties(klass, N_PROPERTIES, specs);
}

// What a row's `access` column does in each direction, with `Type` the row's type: SET_ in
// set_property, GET_ in get_property. GObject never sets a read-only property.
#define SET_SETTING(member) from_value(Type{}, value, s.member)
#define SET_HANDLED(setter, getter) setter(self, value)
#define SET_READ_ONLY(getter) G_OBJECT_WARN_INVALID_PROPERTY_ID(object, prop_id, pspec)
#define GET_SETTING(member) to_value(Type{}, value, s.member)
#define GET_HANDLED(setter, getter) getter(self, value)
#define GET_READ_ONLY(getter) getter(self, value)

// A row as a case of the switch in the direction `dir` (SET_ or GET_).
#define PROJTRACK_PROPERTY_CASE(dir, id, type, access) \
  case PROP_##id: {                                    \
    using Type [[maybe_unused]] = type;                \
    dir##access;                                       \
    break;                                             \
  }

void set_property(GObject* object, guint prop_id, const GValue* value, GParamSpec* pspec) {
  auto* self = GST_PROJTRACK(object);
  GST_OBJECT_LOCK(self);
  ElementSettings& s = self->state->locked.settings;
  switch (prop_id) {
#define PROJTRACK_PROPERTY(id, name, nick, type, range, def, flags, access, blurb) \
  PROJTRACK_PROPERTY_CASE(SET_, id, type, access)
#include "property_table.def"
#undef PROJTRACK_PROPERTY
    default:
      G_OBJECT_WARN_INVALID_PROPERTY_ID(object, prop_id, pspec);
      break;
  }
  GST_OBJECT_UNLOCK(self);
}

void get_property(GObject* object, guint prop_id, GValue* value, GParamSpec* pspec) {
  auto* self = GST_PROJTRACK(object);
  GST_OBJECT_LOCK(self);
  const ElementSettings& s = self->state->locked.settings;
  switch (prop_id) {
#define PROJTRACK_PROPERTY(id, name, nick, type, range, def, flags, access, blurb) \
  PROJTRACK_PROPERTY_CASE(GET_, id, type, access)
#include "property_table.def"
#undef PROJTRACK_PROPERTY
    default:
      G_OBJECT_WARN_INVALID_PROPERTY_ID(object, prop_id, pspec);
      break;
  }
  GST_OBJECT_UNLOCK(self);
}

}  // namespace projtrack::gst
