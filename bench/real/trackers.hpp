// The trackers projtrack-real runs side by side, each frame by frame over a clip: the element,
// gst-plugins-bad's cvtracker and OpenCV's CamShift, and what each reports on a frame.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "clip.hpp"

namespace projtrack::bench {

struct Report {
  std::string status = "none";  // projtrack's status; "ok" / "lost" for the box trackers
  bool has_features = false;    // a centroid, an area and a box measured on this frame
  Point2d centroid;
  double area = 0;
  Rect box;
  bool has_pose = false;
  double position_x = 0, position_y = 0, depth = 0;
  bool push = false, acquired = false;
  double us = 0;           // time to process the frame
  unsigned long work = 0;  // the element's work on the frame (units of max-work)
  std::string detail;
};

// One tracker over one clip, frame after frame.
struct Tracker {
  std::string name;
  std::function<Report(int)> process;
};

// The properties of every run, per clip and tracker, for meta.json: what the report says was run.
extern std::map<std::string, std::map<std::string, std::string>> run_properties;

// The element with `props` (gst-launch syntax), fed the clip's I420 buffers.
Tracker projtrack_tracker(const Clip& c, const std::string& name, const std::string& props);
// gst-plugins-bad's cvtracker, started from `box`; its ROI meta is the box.
Tracker cvtracker_tracker(const Clip& c, const std::string& algorithm, const Rect& box);
// OpenCV's CamShift on a hue-saturation histogram of `box` on the first frame.
Tracker camshift_tracker(const Clip& c, const Rect& box);

constexpr int kCamShiftHueBins = 30, kCamShiftSatBins = 32;
constexpr int kCamShiftSatMin = 30, kCamShiftValMin = 10;

// The nick of the element's default method, read from its property.
std::string default_method();

}  // namespace projtrack::bench
