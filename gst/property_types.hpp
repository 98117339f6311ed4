// What the type and range columns of the property table (property_table.def) mean: the GParamSpec
// a row builds, and how a GValue of that type is read into its ElementSettings member and written
// back. A type is a tag naming its Range, so that a row's `(min, max)` constructs the range of its
// type.
#pragma once

#include <gst/gst.h>

#include <vector>

#include "projtrack/geometry.hpp"

namespace projtrack::gst {

template <class T>
struct Bounds {
  Bounds(T lo, T hi) : min(lo), max(hi) {}
  T min, max;
};

struct Uint {
  using Range = Bounds<guint>;
};
struct Int {
  using Range = Bounds<gint>;
};
struct Double {
  using Range = Bounds<gdouble>;
};
struct Boolean {
  struct Range {};  // `()`: a boolean has no range
};
struct Enum {
  struct Range {  // `(GST_TYPE_...)`: the enum's GType
    explicit Range(GType t) : type(t) {}
    GType type;
  };
};
struct Flags {
  struct Range {  // `(GST_TYPE_...)`: the flags' GType
    explicit Range(GType t) : type(t) {}
    GType type;
  };
};
// A box <x, y, width, height> as a GstValueArray of ints; its range is each coordinate's.
struct Box {
  struct Range {
    Range(gint lo, gint hi) : min(lo), max(hi) {}
    gint min, max;
  };
};

// Several tuples of ints, <<x, y, width, height>, ...> or <<x, y>, ...>: a GstValueArray of
// GstValueArrays of ints, so that gst-launch-1.0 parses the nested syntax (an array spec of plain
// ints makes GStreamer 1.22's deserializer crash on a nested '<'). Read and written by the row's
// handlers, which say which tuples are refused.
struct Tuples {
  struct Range {
    Range(gint lo, gint hi) : min(lo), max(hi) {}
    gint min, max;
  };
};
// A list of ints <a, b, ...> (a GstValueArray of ints), into a std::vector<int>.
struct Ints {
  struct Range {
    Range(gint lo, gint hi) : min(lo), max(hi) {}
    gint min, max;
  };
};

inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Uint::Range r,
                              guint def, GParamFlags flags) {
  return g_param_spec_uint(name, nick, blurb, r.min, r.max, def, flags);
}
inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Int::Range r,
                              gint def, GParamFlags flags) {
  return g_param_spec_int(name, nick, blurb, r.min, r.max, def, flags);
}
inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb,
                              Double::Range r, gdouble def, GParamFlags flags) {
  return g_param_spec_double(name, nick, blurb, r.min, r.max, def, flags);
}
inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Boolean::Range,
                              bool def, GParamFlags flags) {
  return g_param_spec_boolean(name, nick, blurb, def, flags);
}
template <class E>
GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Enum::Range r, E def,
                       GParamFlags flags) {
  return g_param_spec_enum(name, nick, blurb, r.type, static_cast<gint>(def), flags);
}
inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Flags::Range r,
                              guint def, GParamFlags flags) {
  return g_param_spec_flags(name, nick, blurb, r.type, def, flags);
}
// A GstValueArray's default is always the empty array: the row's default must be the empty box.
inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Box::Range r,
                              const Rect& def, GParamFlags flags) {
  g_assert(def.empty());
  GParamSpec* coordinate =
      g_param_spec_int("coordinate", "Coordinate", "x, y, width or height", r.min, r.max, 0,
                       static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS));
  return gst_param_spec_array(name, nick, blurb, coordinate, flags);
}

// A GstValueArray's default is always the empty array: the row's default must be empty too.
template <class T>
GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Tuples::Range r,
                       const std::vector<T>& def, GParamFlags flags) {
  g_assert(def.empty());
  const auto static_rw = static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS);
  GParamSpec* coordinate = g_param_spec_int("coordinate", "Coordinate", "one number of a tuple",
                                            r.min, r.max, 0, static_rw);
  GParamSpec* tuple =
      gst_param_spec_array("tuple", "Tuple", "the numbers of one start", coordinate, static_rw);
  return gst_param_spec_array(name, nick, blurb, tuple, flags);
}
inline GParamSpec* param_spec(const char* name, const char* nick, const char* blurb, Ints::Range r,
                              const std::vector<int>& def, GParamFlags flags) {
  g_assert(def.empty());
  GParamSpec* item =
      g_param_spec_int("item", "Item", "one number", r.min, r.max, 0,
                       static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS));
  return gst_param_spec_array(name, nick, blurb, item, flags);
}

// A GValue of the row's type into its ElementSettings member, and back: the member's own C++ type
// (an int for a uint property, the library's enum for an enum one).
inline void from_value(Uint, const GValue* v, int& member) {
  member = static_cast<int>(g_value_get_uint(v));
}
inline void to_value(Uint, GValue* v, int member) { g_value_set_uint(v, member); }
inline void from_value(Double, const GValue* v, double& member) { member = g_value_get_double(v); }
inline void to_value(Double, GValue* v, double member) { g_value_set_double(v, member); }
inline void from_value(Boolean, const GValue* v, bool& member) { member = g_value_get_boolean(v); }
inline void to_value(Boolean, GValue* v, bool member) { g_value_set_boolean(v, member); }
inline void from_value(Flags, const GValue* v, unsigned& member) { member = g_value_get_flags(v); }
inline void to_value(Flags, GValue* v, unsigned member) { g_value_set_flags(v, member); }
// A list of ints: its int items (the param spec's validation keeps only those).
inline void from_value(Ints, const GValue* v, std::vector<int>& member) {
  member.clear();
  for (guint i = 0; i < gst_value_array_get_size(v); ++i)
    if (const GValue* item = gst_value_array_get_value(v, i); G_VALUE_HOLDS_INT(item))
      member.push_back(g_value_get_int(item));
}
inline void to_value(Ints, GValue* v, const std::vector<int>& member) {
  for (int m : member) {
    GValue item = G_VALUE_INIT;
    g_value_init(&item, G_TYPE_INT);
    g_value_set_int(&item, m);
    gst_value_array_append_and_take_value(v, &item);
  }
}
template <class E>
void from_value(Enum, const GValue* v, E& member) {
  member = static_cast<E>(g_value_get_enum(v));
}
template <class E>
void to_value(Enum, GValue* v, E member) {
  g_value_set_enum(v, static_cast<gint>(member));
}

}  // namespace projtrack::gst
