// What projtrack-speed writes: see output.hpp.
#include "output.hpp"

#include <gst/gst.h>

#include <fstream>
#include <opencv2/core/utility.hpp>
#include <thread>

#include "machine.hpp"
#include "projtrack/tracker.hpp"
#include "models/edges/edge_region.hpp"

namespace projtrack::bench {

std::string kDefaultMethod;
const std::string kElementDefault = "projtrack element default";
std::FILE* csv = nullptr;

void row(const std::string& section, const Clip* c, const std::string& what, const std::string& key,
         double value) {
  std::fprintf(csv, "%s,%s,%dx%d,\"%s\",%s,%.6g\n", section.c_str(), c ? c->name.c_str() : "",
               c ? c->width : 0, c ? c->height : 0, what.c_str(), key.c_str(), value);
}

void write_meta(const std::string& dir, const std::string& measured) {
  std::ofstream meta(dir + "/meta.json");
  meta << "{\n  \"measured\": \"" << measured << "\",\n  \"cpu\": \"" << cpu_model()
       << "\",\n  \"cores\": " << std::thread::hardware_concurrency() << ",\n  \"opencv\": \""
       << CV_VERSION << "\",\n  \"gstreamer\": \"" << gst_version_string()
       << "\",\n  \"opencv_threads\": " << cv::getNumThreads()
       << ",\n  \"edge_margin\": " << TrackerParams{}.edge_margin
       << ",\n  \"least_margin_px\": " << kLeastEdgeMargin << ",\n  \"canny\": ["
       << EdgeParams{}.low << ", " << EdgeParams{}.high << "]\n}\n";
}

}  // namespace projtrack::bench
