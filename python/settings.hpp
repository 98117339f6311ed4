// The tracker's settings as Python gives them: keywords named as the element's properties
// (keyword_table.def), mapped onto the library's settings bundle and checked once, with its one
// validate(), at construction: a bad one is a ValueError that says which and why, never a tracker
// that reports it per frame.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "projtrack/sample_clock.hpp"
#include "projtrack/settings.hpp"

namespace projtrack::python {

// What a Python tracker is set with: the bundle, the rate that times frames given no time and, for
// a MultiTracker, the most objects it follows at once.
struct TrackerOptions {
  Settings settings;
  double fps = kAssumedFrameRate;  // the element's rate for buffers without timestamps
  int max_objects = 0;             // MultiTracker's keyword (its default 8); 0: Tracker's, none
};

// A MultiTracker's options before its keywords: Python's defaults, and 8 objects at the most.
TrackerOptions multi_defaults();

// The bundle's defaults as Python starts from them: the library's, but for acquisition, which is
// manual, as an OpenCV-style tracker starts from init(). The one default Python holds.
Settings python_defaults();

// The options `kwargs` name over `defaults` (python_defaults() for a Tracker, multi_defaults()
// for a MultiTracker, which also takes max_objects): TypeError for an unknown keyword or a value
// of the wrong type, ValueError naming the setting that is out of range. `cls` names the class in
// the errors.
TrackerOptions options_from(const pybind11::kwargs& kwargs,
                            const TrackerOptions& defaults = {python_defaults()},
                            const char* cls = "Tracker");
// Every keyword and its value, by the names the class takes.
pybind11::dict options_dict(const TrackerOptions& o);
// The keywords and their `defaults`, one line each, for the class's docstring.
std::string keywords_doc(const TrackerOptions& defaults = {python_defaults()});

}  // namespace projtrack::python
