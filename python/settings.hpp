// The tracker's settings as Python gives them (names, numbers), checked once at construction: a
// bad one is a ValueError that says which and why, never a tracker that reports it per frame.
#pragma once

#include <string>

#include "projtrack/edge_detection.hpp"
#include "projtrack/method.hpp"
#include "projtrack/params.hpp"
#include "projtrack/tracker_params.hpp"

namespace projtrack::python {

// What the constructor's keyword arguments say, before they are checked.
struct Options {
  std::string method = "gap-tolerant-filling";
  std::string model = "appearance";
  std::string acquisition = "manual";  // an OpenCV-style tracker starts from init()
  Params params;
  EdgeParams edges;
  bool smoothing = true;
  double max_work = TrackerParams{}.max_work;
  double fps = 30;  // the frame rate that times frames given without a time
};

struct Settings {
  Method method = Method::GapTolerantFilling;
  Params params;
  EdgeParams edges;
  TrackerParams tracker;
  double fps = 30;
};

// The settings `o` names; throws pybind11::value_error naming the option that is wrong.
Settings make_settings(const Options& o);

// The names the options accept (for messages and the docs).
const char* model_name(ObjectModelKind k);
const char* acquisition_name(Acquisition a);
std::string method_names();  // "ray-casting, iterative-ray-casting, ..."

}  // namespace projtrack::python
