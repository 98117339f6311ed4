/* The meta projtrack attaches to every buffer it tracks, for applications in C.
 *
 * A GstCustomMeta (GStreamer >= 1.20) named "GstProjtrackMeta" whose structure holds the features
 * in the frame of the buffer that carries it: projtrack's own transform function scales them when
 * videoscale (or videoconvert, which calls the same transform) changes the frame's size, and
 * copies them when a buffer is copied, so they survive where the ROI meta's parameters do not.
 * Header-only: an application does not link against a plugin; it finds the meta by its name once
 * the plugin is loaded (a pipeline holding projtrack has loaded it). Python reads the same:
 * buffer.get_custom_meta("GstProjtrackMeta").get_structure(). docs/element.md lists the fields.
 *
 *   const GstStructure *s = gst_buffer_get_projtrack_meta (buffer);
 *   GstProjtrackFeatures f;
 *   if (gst_projtrack_features_read (s, &f))
 *     g_print ("track %d: centroid %.1f,%.1f area %.0f\n", f.track_id, f.centroid_x,
 *         f.centroid_y, f.area);
 */
#ifndef __GST_PROJTRACK_META_H__
#define __GST_PROJTRACK_META_H__

#include <gst/gst.h>

G_BEGIN_DECLS

#define GST_PROJTRACK_META_NAME "GstProjtrackMeta"

/* The features of the first projtrack meta on `buffer` (the last projtrack it went through), or
 * NULL. Owned by the buffer: valid while it is. */
static inline const GstStructure* gst_buffer_get_projtrack_meta(GstBuffer* buffer) {
  GstCustomMeta* meta = gst_buffer_get_custom_meta(buffer, GST_PROJTRACK_META_NAME);
  return meta ? gst_custom_meta_get_structure(meta) : NULL;
}

/* One projtrack meta after the other (one per projtrack element the buffer went through, and per
 * object each follows: their "element" and "id" fields name them): start with *state = NULL; NULL
 * when there are no more. */
static inline const GstStructure* gst_buffer_iterate_projtrack_meta(GstBuffer* buffer,
                                                                    gpointer* state) {
  const GstMetaInfo* info = gst_meta_get_info(GST_PROJTRACK_META_NAME);
  GstMeta* meta = info ? gst_buffer_iterate_meta_filtered(buffer, state, info->api) : NULL;
  return meta ? gst_custom_meta_get_structure((GstCustomMeta*)meta) : NULL;
}

/* The meta's scalar fields as C values. The strings belong to the structure. */
typedef struct {
  const gchar* status;            /* "ok", "reached-border" or "covers-frame" */
  const gchar* element;           /* the name of the projtrack element that tracked it */
  const gchar* method;            /* the estimator's nick */
  gint track_id;                  /* > 0; new on every acquisition, the ROI meta's id */
  gint frame_width, frame_height; /* the frame the coordinates below refer to */
  gdouble centroid_x, centroid_y; /* px, pixel centres at integer coordinates */
  gdouble area;                   /* px² */
  gint x, y, width, height;       /* bounding box */
  gint inner_point_x, inner_point_y;
  gdouble position_x, position_y, depth; /* the 3D pointer */
  gboolean push;                         /* a push completed on this frame */
  gint id; /* an object among several (start-boxes, add-box...): its id, from 1; 0: the single
              track */
} GstProjtrackFeatures;

/* Fills `f` from a projtrack meta's structure `s`; FALSE (and `f` partly filled) when `s` is NULL
 * or lacks a field. */
static inline gboolean gst_projtrack_features_read(const GstStructure* s, GstProjtrackFeatures* f) {
  if (!s) return FALSE;
  f->status = gst_structure_get_string(s, "status");
  f->element = gst_structure_get_string(s, "element");
  f->method = gst_structure_get_string(s, "method");
  f->push = g_strcmp0(gst_structure_get_string(s, "gesture"), "push") == 0;
  f->id = 0;
  gst_structure_get_int(s, "id", &f->id); /* absent: the single track */
  return f->status && f->element && f->method &&
         gst_structure_get(s, "track-id", G_TYPE_INT, &f->track_id, "frame-width", G_TYPE_INT,
                           &f->frame_width, "frame-height", G_TYPE_INT, &f->frame_height,
                           "centroid-x", G_TYPE_DOUBLE, &f->centroid_x, "centroid-y", G_TYPE_DOUBLE,
                           &f->centroid_y, "area", G_TYPE_DOUBLE, &f->area, "x", G_TYPE_INT, &f->x,
                           "y", G_TYPE_INT, &f->y, "width", G_TYPE_INT, &f->width, "height",
                           G_TYPE_INT, &f->height, "inner-point-x", G_TYPE_INT, &f->inner_point_x,
                           "inner-point-y", G_TYPE_INT, &f->inner_point_y, "position-x",
                           G_TYPE_DOUBLE, &f->position_x, "position-y", G_TYPE_DOUBLE,
                           &f->position_y, "depth", G_TYPE_DOUBLE, &f->depth, NULL);
}

/* The outline: "outline" is a GstValueArray of polygons (one per piece of the silhouette, the
 * largest first), each a GstValueArray of ints x0, y0, x1, y1, ... in frame coordinates. The
 * number of polygons (0 without a silhouette, e.g. object-model=edges). */
static inline guint gst_projtrack_outline_n_polygons(const GstStructure* s) {
  const GValue* outline = s ? gst_structure_get_value(s, "outline") : NULL;
  return outline && GST_VALUE_HOLDS_ARRAY(outline) ? gst_value_array_get_size(outline) : 0;
}

/* Vertex `i` of polygon `polygon` into *x, *y; FALSE past the last vertex. */
static inline gboolean gst_projtrack_outline_vertex(const GstStructure* s, guint polygon, guint i,
                                                    gint* x, gint* y) {
  const GValue *p, *vx, *vy;
  if (polygon >= gst_projtrack_outline_n_polygons(s)) return FALSE;
  p = gst_value_array_get_value(gst_structure_get_value(s, "outline"), polygon);
  if (!GST_VALUE_HOLDS_ARRAY(p) || i >= gst_value_array_get_size(p) / 2) return FALSE;
  vx = gst_value_array_get_value(p, 2 * i);
  vy = gst_value_array_get_value(p, 2 * i + 1);
  if (!G_VALUE_HOLDS_INT(vx) || !G_VALUE_HOLDS_INT(vy)) return FALSE;
  *x = g_value_get_int(vx);
  *y = g_value_get_int(vy);
  return TRUE;
}

G_END_DECLS

#endif /* __GST_PROJTRACK_META_H__ */
