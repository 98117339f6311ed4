// The element's enum and flags types, as gst-inspect-1.0 shows them: method (from the table of
// methods), edge-detector, acquisition, object-model, updates and draw-flags. Each is registered on
// its first use; a function-local static makes that thread-safe.
#include "gstprojtrack.h"
#include "projtrack/edge_detection.hpp"
#include "projtrack/method.hpp"
#include "projtrack/tracker_params.hpp"
#include "settings.hpp"

using projtrack::Acquisition;
using projtrack::EdgeDetector;
using projtrack::ObjectModelKind;
using projtrack::gst::Updates;

// One value per row of the table of methods (include/projtrack/method_table.def): its nick and
// description.
GType gst_projtrack_method_get_type(void) {
  static GEnumValue values[projtrack::kMethodCount + 1];  // and the terminating zeros
  static const GType type = [] {
    for (const projtrack::MethodInfo& m : projtrack::kMethods)
      values[static_cast<int>(m.method)] = {static_cast<gint>(m.method), m.description, m.nick};
    return g_enum_register_static("GstProjtrackMethod", values);
  }();
  return type;
}

GType gst_projtrack_edge_detector_get_type(void) {
  static const GEnumValue values[] = {
      {static_cast<gint>(EdgeDetector::Canny), "Canny (hysteresis thresholds low/high)", "canny"},
      {static_cast<gint>(EdgeDetector::Sobel), "Sobel |Gx|+|Gy| >= low (thick edges)", "sobel"},
      {static_cast<gint>(EdgeDetector::Input),
       "Input: the frame already is an edge map (luma above black = edge)", "input"},
      {0, nullptr, nullptr}};
  static const GType type = g_enum_register_static("GstProjtrackEdgeDetector", values);
  return type;
}

GType gst_projtrack_acquisition_get_type(void) {
  static const GEnumValue values[] = {
      {static_cast<gint>(Acquisition::Manual), "Manual: wait for an inner point or a click",
       "manual"},
      {static_cast<gint>(Acquisition::Center), "Center: track what is at the frame centre",
       "center"},
      {static_cast<gint>(Acquisition::Auto),
       "Auto: the object that moves (appearance: the moving region of colours apart from the "
       "border's; edges: the most compact moving region)",
       "auto"},
      {0, nullptr, nullptr}};
  static const GType type = g_enum_register_static("GstProjtrackAcquisition", values);
  return type;
}

GType gst_projtrack_object_model_get_type(void) {
  static const GEnumValue values[] = {
      {static_cast<gint>(ObjectModelKind::Edges),
       "Edges: the paper's tracker, the estimator on the edge image alone", "edges"},
      {static_cast<gint>(ObjectModelKind::Appearance),
       "Appearance: the whole object's silhouette from its colours, its edges and its motion; "
       "the estimator runs on its outline",
       "appearance"},
      {static_cast<gint>(ObjectModelKind::Flow),
       "Flow: the whole object carried along the picture's motion and cut from its surroundings "
       "by colour and motion; the estimator runs on its outline",
       "flow"},
      {0, nullptr, nullptr}};
  static const GType type = g_enum_register_static("GstProjtrackObjectModel", values);
  return type;
}

GType gst_projtrack_updates_get_type(void) {
  static const GEnumValue values[] = {
      {static_cast<gint>(Updates::EveryFrame), "A message for every frame", "every-frame"},
      {static_cast<gint>(Updates::OnChange),
       "A message when the status changes, an object is acquired, or a gesture completes",
       "on-change"},
      {static_cast<gint>(Updates::None), "No messages (the ROI meta is still attached)", "none"},
      {0, nullptr, nullptr}};
  static const GType type = g_enum_register_static("GstProjtrackUpdates", values);
  return type;
}

GType gst_projtrack_draw_flags_get_type(void) {
  using namespace projtrack::gst;
  static const GFlagsValue values[] = {
      {kDrawStatus, "The text: status and why, x, y and depth, the method", "status"},
      {kDrawOutline, "The object's outline (its silhouette)", "outline"},
      {kDrawBox, "The object's bounding box", "box"},
      {kDrawCentroid, "The centroid's cross", "centroid"},
      {kDrawInnerPoint, "The inner point for the next frame", "inner-point"},
      {kDrawGrid, "What the method did: grid lines, filled pixels, blocks or rays", "grid"},
      {0, nullptr, nullptr}};
  static const GType type = g_flags_register_static("GstProjtrackDrawFlags", values);
  return type;
}
