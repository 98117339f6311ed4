#include "meta.hpp"

#include <gst/video/video.h>

#include <algorithm>
#include <cmath>

#include "element.hpp"
#include "gstprojtrackmeta.h"

namespace projtrack::gst {

namespace {

// A pixel index (its centre at +0.5) of an axis `factor` times as long, within [0, size).
int scaled_pixel(int v, double factor, int size) {
  const double p = std::floor((v + 0.5) * factor);
  return static_cast<int>(std::clamp(p, 0.0, static_cast<double>(std::max(0, size - 1))));
}

void scale_point(GstStructure* s, const char* fx, const char* fy, double sx, double sy, int w,
                 int h) {
  gint x = 0, y = 0;
  if (gst_structure_get_int(s, fx, &x) && gst_structure_get_int(s, fy, &y))
    gst_structure_set(s, fx, G_TYPE_INT, scaled_pixel(x, sx, w), fy, G_TYPE_INT,
                      scaled_pixel(y, sy, h), nullptr);
}

// The box's first and one-past-last pixels follow the picture: it still holds what it held.
void scale_box(GstStructure* s, double sx, double sy, int w, int h) {
  gint x = 0, y = 0, bw = 0, bh = 0;
  if (!gst_structure_get(s, "x", G_TYPE_INT, &x, "y", G_TYPE_INT, &y, "width", G_TYPE_INT, &bw,
                         "height", G_TYPE_INT, &bh, nullptr))
    return;
  const auto edge = [](double v, int size) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(size)));
  };
  const int x0 = edge(std::floor(x * sx), w), y0 = edge(std::floor(y * sy), h);
  const int x1 = edge(std::ceil((static_cast<double>(x) + bw) * sx), w);
  const int y1 = edge(std::ceil((static_cast<double>(y) + bh) * sy), h);
  gst_structure_set(s, "x", G_TYPE_INT, x0, "y", G_TYPE_INT, y0, "width", G_TYPE_INT, x1 - x0,
                    "height", G_TYPE_INT, y1 - y0, nullptr);
}

void scale_outline(GstStructure* s, double sx, double sy, int w, int h) {
  const GValue* outline = gst_structure_get_value(s, "outline");
  if (!outline || !GST_VALUE_HOLDS_ARRAY(outline)) return;
  GValue out = G_VALUE_INIT;
  gst_value_array_init(&out, gst_value_array_get_size(outline));
  for (guint k = 0; k < gst_value_array_get_size(outline); ++k) {
    const GValue* polygon = gst_value_array_get_value(outline, k);
    if (!GST_VALUE_HOLDS_ARRAY(polygon)) continue;
    GValue scaled = G_VALUE_INIT;
    gst_value_array_init(&scaled, gst_value_array_get_size(polygon));
    for (guint i = 0; i < gst_value_array_get_size(polygon); ++i) {
      const GValue* v = gst_value_array_get_value(polygon, i);
      GValue c = G_VALUE_INIT;
      g_value_init(&c, G_TYPE_INT);
      const bool is_x = i % 2 == 0;
      if (G_VALUE_HOLDS_INT(v))
        g_value_set_int(&c, scaled_pixel(g_value_get_int(v), is_x ? sx : sy, is_x ? w : h));
      gst_value_array_append_and_take_value(&scaled, &c);
    }
    gst_value_array_append_and_take_value(&out, &scaled);
  }
  gst_structure_take_value(s, "outline", &out);
}

// copy: the same features; videoscale's and videoconvert's scale: scaled_features(). Any other
// transform (videoflip's, videocrop's in GStreamer 1.22 do not call one) drops the meta.
gboolean transform(GstBuffer* dest, GstCustomMeta* meta, GstBuffer*, GQuark type, gpointer data,
                   gpointer) {
  const GstStructure* features = gst_custom_meta_get_structure(meta);
  if (GST_META_TRANSFORM_IS_COPY(type)) {
    add_projtrack_meta(dest, features);
    return TRUE;
  }
  GstStructure* out = nullptr;
  if (GST_VIDEO_META_TRANSFORM_IS_SCALE(type)) {
    const auto* t = static_cast<const GstVideoMetaTransform*>(data);
    out = scaled_features(features, GST_VIDEO_INFO_WIDTH(t->in_info),
                          GST_VIDEO_INFO_HEIGHT(t->in_info), GST_VIDEO_INFO_WIDTH(t->out_info),
                          GST_VIDEO_INFO_HEIGHT(t->out_info));
  }
  if (!out) {
    GST_DEBUG("GstProjtrackMeta not carried over a %s transform", g_quark_to_string(type));
    return FALSE;
  }
  add_projtrack_meta(dest, out);
  gst_structure_free(out);
  return TRUE;
}

}  // namespace

const GstMetaInfo* projtrack_meta_info() {
  static const GstMetaInfo* info = [] {
    // The ROI meta's tags: elements that change the frame's size call the transform (videoscale,
    // videoconvert); those that change its orientation and cannot transform it drop it.
    const gchar* tags[] = {GST_META_TAG_VIDEO_STR, GST_META_TAG_VIDEO_SIZE_STR,
                           GST_META_TAG_VIDEO_ORIENTATION_STR, nullptr};
    const GstMetaInfo* registered =
        gst_meta_register_custom(GST_PROJTRACK_META_NAME, tags, transform, nullptr, nullptr);
    // Another copy of the plugin may have registered it first (same name, same fields).
    return registered ? registered : gst_meta_get_info(GST_PROJTRACK_META_NAME);
  }();
  return info;
}

void add_projtrack_meta(GstBuffer* buffer, const GstStructure* features) {
  projtrack_meta_info();
  GstCustomMeta* meta = gst_buffer_add_custom_meta(buffer, GST_PROJTRACK_META_NAME);
  if (meta) {
    GstStructure* s = gst_custom_meta_get_structure(meta);
    gst_structure_foreach(
        features,
        [](GQuark field, const GValue* value, gpointer to) -> gboolean {
          gst_structure_id_set_value(static_cast<GstStructure*>(to), field, value);
          return TRUE;
        },
        s);
  }
}

GstStructure* scaled_features(const GstStructure* features, int in_width, int in_height,
                              int out_width, int out_height) {
  if (in_width <= 0 || in_height <= 0 || out_width <= 0 || out_height <= 0) return nullptr;
  const double sx = static_cast<double>(out_width) / in_width;
  const double sy = static_cast<double>(out_height) / in_height;
  GstStructure* s = gst_structure_copy(features);
  gdouble cx = 0, cy = 0, area = 0;
  if (gst_structure_get_double(s, "centroid-x", &cx) &&
      gst_structure_get_double(s, "centroid-y", &cy))
    gst_structure_set(s, "centroid-x", G_TYPE_DOUBLE, (cx + 0.5) * sx - 0.5, "centroid-y",
                      G_TYPE_DOUBLE, (cy + 0.5) * sy - 0.5, nullptr);
  if (gst_structure_get_double(s, "area", &area))
    gst_structure_set(s, "area", G_TYPE_DOUBLE, area * sx * sy, nullptr);
  scale_box(s, sx, sy, out_width, out_height);
  scale_point(s, "inner-point-x", "inner-point-y", sx, sy, out_width, out_height);
  scale_outline(s, sx, sy, out_width, out_height);
  gst_structure_set(s, "frame-width", G_TYPE_INT, out_width, "frame-height", G_TYPE_INT, out_height,
                    nullptr);
  return s;
}

}  // namespace projtrack::gst
