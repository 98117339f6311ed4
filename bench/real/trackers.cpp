#include "trackers.hpp"

#include <gst/video/video.h>

#include <chrono>
#include <cstring>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>

#include "element_harness.hpp"

namespace projtrack::bench {

std::map<std::string, std::map<std::string, std::string>> run_properties;

namespace {

using Clock = std::chrono::steady_clock;

double micros_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

double field_double(const GstStructure* s, const char* name) {
  double v = 0;
  gst_structure_get_double(s, name, &v);
  return v;
}

int field_int(const GstStructure* s, const char* name) {
  int v = 0;
  gst_structure_get_int(s, name, &v);
  return v;
}

bool is_tracking_status(const std::string& s) {
  return s == "ok" || s == "reached-border" || s == "covers-frame";
}

// The element's message about this frame.
void read_projtrack_message(const GstStructure* s, Report& r) {
  r.status = gst_structure_get_string(s, "status");
  // A lost track's message holds the last accepted features: not a measurement of this frame.
  r.has_features = is_tracking_status(r.status) && gst_structure_has_field(s, "area");
  if (gst_structure_has_field(s, "area")) {
    r.centroid = {field_double(s, "centroid-x"), field_double(s, "centroid-y")};
    r.area = field_double(s, "area");
    r.box = {field_int(s, "x"), field_int(s, "y"), field_int(s, "width"), field_int(s, "height")};
  }
  if (gst_structure_has_field(s, "depth")) {
    r.has_pose = true;
    r.position_x = field_double(s, "position-x");
    r.position_y = field_double(s, "position-y");
    r.depth = field_double(s, "depth");
  }
  const char* g = gst_structure_get_string(s, "gesture");
  r.push = g && std::strcmp(g, "push") == 0;
  gboolean acquired = FALSE;
  r.acquired = gst_structure_get_boolean(s, "acquired", &acquired) && acquired;
  if (const char* d = gst_structure_get_string(s, "detail")) r.detail = d;
  guint64 work = 0;
  if (gst_structure_get_uint64(s, "work", &work)) r.work = work;
}

}  // namespace

Tracker projtrack_tracker(const Clip& c, const std::string& name, const std::string& props) {
  run_properties[c.name][name] = props;
  auto h = std::make_shared<ElementHarness>("projtrack " + props, c.caps("I420"), true);
  return {name, [h, &c](int i) {
            Report r;
            const auto t0 = Clock::now();
            GstBuffer* out = h->push_pull(c.i420_buffers[i]);
            r.us = micros_since(t0);
            if (out) gst_buffer_unref(out);
            for (GstMessage* m : h->take_messages()) {
              const GstStructure* s = gst_message_get_structure(m);
              if (gst_structure_has_name(s, "projtrack")) read_projtrack_message(s, r);
              gst_message_unref(m);
            }
            return r;
          }};
}

// gst-plugins-bad's cvtracker: started from the first frame's true box; its ROI meta is the box.
// On the first frame it only starts (no meta): that frame reports the box it was given.
Tracker cvtracker_tracker(const Clip& c, const std::string& algorithm, const Rect& b) {
  const std::string launch = "cvtracker algorithm=" + algorithm +
                             " draw-rect=false object-initial-x=" + std::to_string(b.x) +
                             " object-initial-y=" + std::to_string(b.y) +
                             " object-initial-width=" + std::to_string(b.width) +
                             " object-initial-height=" + std::to_string(b.height);
  run_properties[c.name]["cvtracker " + algorithm] = launch;
  auto h = std::make_shared<ElementHarness>(launch, c.caps("RGB"), false);
  return {"cvtracker " + algorithm, [h, &c, b](int i) {
            Report r;
            const auto t0 = Clock::now();
            GstBuffer* out = h->push_pull(c.rgb_buffers[i]);
            r.us = micros_since(t0);
            std::optional<Rect> box;
            if (i == 0) box = b;
            if (out) {
              gpointer state = nullptr;
              while (GstMeta* m = gst_buffer_iterate_meta_filtered(
                         out, &state, GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE)) {
                const auto* roi = reinterpret_cast<GstVideoRegionOfInterestMeta*>(m);
                // Its box is kept as unsigned: a box partly left of or above the frame wraps.
                box = Rect{static_cast<int>(roi->x), static_cast<int>(roi->y),
                           static_cast<int>(roi->w), static_cast<int>(roi->h)};
              }
              gst_buffer_unref(out);
            }
            if (box) {
              r.status = "ok";
              r.has_features = true;
              r.box = *box;
              r.centroid = {box->x + (box->width - 1) / 2.0, box->y + (box->height - 1) / 2.0};
              r.area = static_cast<double>(box->width) * box->height;
            } else {
              r.status = "lost";
            }
            return r;
          }};
}

// OpenCV's CamShift on the back projection of a 2-D hue–saturation histogram of the first
// frame's true box, as issue 12 asks (OpenCV's camshiftdemo uses a hue-only histogram; hue and
// saturation together also tell a grey object from a white one). Pixels outside camshiftdemo's
// mask (saturation below kCamShiftSatMin or value below kCamShiftValMin) count neither in the
// histogram nor in the back projection. CamShift runs from the last window, and a collapsed
// window restarts around its centre as in the demo. Given BGR frames, it converts them to HSV
// itself (timed).

Tracker camshift_tracker(const Clip& c, const Rect& box) {
  struct State {
    cv::Mat hist, bgr, hsv, mask, backproj;
    cv::Rect window;
  };
  auto st = std::make_shared<State>();
  return {"CamShift", [st, &c, box](int i) {
            Report r;
            st->bgr = to_bgr(c.frames[i]);  // not timed: the input
            const auto t0 = Clock::now();
            const float hranges[] = {0, 180}, sranges[] = {0, 256};
            const float* ranges[] = {hranges, sranges};
            const int sizes[] = {kCamShiftHueBins, kCamShiftSatBins}, channels[] = {0, 1};
            cv::cvtColor(st->bgr, st->hsv, cv::COLOR_BGR2HSV);
            cv::inRange(st->hsv, cv::Scalar(0, kCamShiftSatMin, kCamShiftValMin),
                        cv::Scalar(180, 256, 256), st->mask);
            if (i == 0) {
              const Rect& b = box;
              st->window = cv::Rect(b.x, b.y, b.width, b.height) &
                           cv::Rect(0, 0, st->hsv.cols, st->hsv.rows);
              cv::Mat roi(st->hsv, st->window), maskroi(st->mask, st->window);
              cv::calcHist(&roi, 1, channels, maskroi, st->hist, 2, sizes, ranges);
              cv::normalize(st->hist, st->hist, 0, 255, cv::NORM_MINMAX);
            }
            cv::calcBackProject(&st->hsv, 1, channels, st->hist, st->backproj, ranges);
            st->backproj &= st->mask;
            cv::RotatedRect rr;
            if (st->window.area() > 0)
              rr = cv::CamShift(
                  st->backproj, st->window,
                  cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 10, 1));
            r.us = micros_since(t0);
            if (st->window.area() <= 1) {  // the demo's recovery: a window around the centre
              const int cols = st->backproj.cols, rows = st->backproj.rows;
              const int rr_ = (std::min(cols, rows) + 5) / 6;
              st->window = cv::Rect(st->window.x - rr_, st->window.y - rr_, 2 * rr_, 2 * rr_) &
                           cv::Rect(0, 0, cols, rows);
              r.status = "lost";
              return r;
            }
            r.status = "ok";
            r.has_features = true;
            const cv::Rect b = rr.boundingRect() & cv::Rect(0, 0, c.width, c.height);
            r.box = {b.x, b.y, b.width, b.height};
            r.centroid = {rr.center.x, rr.center.y};
            r.area = static_cast<double>(rr.size.width) * rr.size.height;
            return r;
          }};
}

// The nick of the element's default method, read from its property.
std::string default_method() {
  GstElement* e = gst_element_factory_make("projtrack", nullptr);
  GParamSpec* spec = g_object_class_find_property(G_OBJECT_GET_CLASS(e), "method");
  const GValue* def = g_param_spec_get_default_value(spec);
  const GEnumValue* v =
      g_enum_get_value(G_PARAM_SPEC_ENUM(spec)->enum_class, g_value_get_enum(def));
  std::string nick = v ? v->value_nick : "";
  gst_object_unref(e);
  return nick;
}

}  // namespace projtrack::bench
