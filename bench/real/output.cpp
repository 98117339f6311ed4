#include "output.hpp"

#include <fstream>
#include <opencv2/imgproc.hpp>
#include <thread>

#include "machine.hpp"
#include "projtrack/method.hpp"
#include "variants.hpp"

namespace projtrack::bench {
namespace {

// The share of the box's pixels whose luma changed by more than kChangedLevels in the last two
// frames: a walking person's box has many, a static region of the background almost none.
double moving_share(const Clip& c, int i, const Rect& box) {
  if (i < 2) return -1;  // not known yet
  const cv::Rect r =
      cv::Rect(box.x, box.y, box.width, box.height) & cv::Rect(0, 0, c.width, c.height);
  if (r.area() <= 0) return 0;
  cv::Mat diff;
  cv::absdiff(c.luma(i)(r), c.luma(i - 2)(r), diff);
  return static_cast<double>(cv::countNonZero(diff > kChangedLevels)) / r.area();
}

// The share of `box`'s pixels on frame `i` that differ from the clip's median frame by more than
// kChangedLevels grey levels: near 0 on a piece of the scene's background (a sign, the lawn), high
// on what passes through it.
double scene_share(const Clip& c, int i, const Rect& box) {
  const cv::Rect r =
      cv::Rect(box.x, box.y, box.width, box.height) & cv::Rect(0, 0, c.width, c.height);
  if (r.area() <= 0) return 0;
  cv::Mat diff;
  cv::absdiff(c.luma(i)(r), c.median_luma()(r), diff);
  return static_cast<double>(cv::countNonZero(diff > kChangedLevels)) / r.area();
}

std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// A JSON string literal.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", ch);
      out += esc;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

void write_clip_meta(std::ofstream& meta, const Clip& c) {
  meta << json_string(c.name) << ": {\"frames\": " << c.pts.size() << ", \"width\": " << c.width
       << ", \"height\": " << c.height << ", \"fps\": " << static_cast<double>(c.fps_n) / c.fps_d
       << ", \"truth\": " << (c.has_truth() ? "true" : "false") << ", \"variant\": \"" << c.variant
       << "\", \"path\": " << json_string(c.path) << ", \"properties\": {";
  bool first = true;
  if (run_properties.count(c.name))
    for (const auto& [name, props] : run_properties.at(c.name)) {
      meta << (first ? "" : ", ") << json_string(name) << ": " << json_string(props);
      first = false;
    }
  meta << "}}";
}

}  // namespace

RunsCsv::RunsCsv(const std::string& path) : f_(std::fopen(path.c_str(), "w")) {
  if (f_)
    std::fprintf(f_,
                 "clip,tracker,group,frame,status,measured,centroid_x,centroid_y,area,x,y,width,"
                 "height,has_pose,position_x,position_y,depth,push,acquired,us,work,moving_share,"
                 "scene_share,detail\n");
}

RunsCsv::~RunsCsv() {
  if (f_) std::fclose(f_);
}

void RunsCsv::write(const Clip& c, const std::string& tracker, const std::string& group, int i,
                    const Report& r) {
  std::fprintf(
      f_,
      "%s,%s,%s,%d,%s,%d,%.3f,%.3f,%.1f,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,%d,%d,%.1f,%lu,%.4f,%.4f,"
      "%s\n",
      c.name.c_str(), csv_text(tracker).c_str(), group.c_str(), i, r.status.c_str(), r.has_features,
      r.centroid.x, r.centroid.y, r.area, r.box.x, r.box.y, r.box.width, r.box.height, r.has_pose,
      r.position_x, r.position_y, r.depth, r.push, r.acquired, r.us, r.work,
      r.has_features ? moving_share(c, i, r.box) : -1.0,
      r.has_features ? scene_share(c, i, r.box) : -1.0, csv_text(r.detail).c_str());
}

void write_meta(const std::string& dir, const std::vector<std::unique_ptr<Clip>>& clips) {
  std::ofstream meta(dir + "/meta.json");
  meta << "{\n  \"measured\": \"" << utc_now() << "\",\n  \"cpu\": \"" << cpu_model()
       << "\",\n  \"cores\": " << std::thread::hardware_concurrency() << ",\n  \"opencv\": \""
       << CV_VERSION << "\",\n  \"gstreamer\": \"" << gst_version_string()
       << "\",\n  \"default_method\": \"" << default_method() << "\",\n  \"methods\": [";
  bool first = true;
  for (const MethodInfo& m : kMethods) {
    meta << (first ? "" : ",") << "\n    {\"name\": " << json_string(std::string(m.nick))
         << ", \"family\": \"" << (m.family == Family::Rays ? "rays" : "fill")
         << "\", \"from_paper\": " << (m.from_paper ? "true" : "false") << "}";
    first = false;
  }
  meta << "\n  ],\n  \"camshift\": {\"histogram\": \"hue-saturation\", \"hue_bins\": "
       << kCamShiftHueBins << ", \"saturation_bins\": " << kCamShiftSatBins
       << ", \"saturation_min\": " << kCamShiftSatMin << ", \"value_min\": " << kCamShiftValMin
       << "},\n  \"variants\": {";
  write_variant_settings(meta);
  meta << "},\n  \"changed_levels\": " << kChangedLevels << ",\n  \"clips\": {";
  for (std::size_t k = 0; k < clips.size(); ++k) {
    meta << (k ? "," : "") << "\n    ";
    write_clip_meta(meta, *clips[k]);
  }
  meta << "\n  }\n}\n";
}

}  // namespace projtrack::bench
