// Where a new object starts, as Python gives it to Tracker and MultiTracker: a point, a box or a
// mask, read and checked against the frame before any tracker changes.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "projtrack/geometry.hpp"

namespace projtrack::python {

// Where a new object starts: `obj` read as an inner point (x, y), a box (x, y, width, height), a
// mask ((H, W) array, non-zero on the object) or, for Either, whichever it is (a 2-D array: a mask;
// else by its count of numbers).
struct Where {
  enum Kind { Nowhere, Point, Box, Mask, Either };
  pybind11::handle obj;
  Kind kind = Nowhere;
  bool restart = false;  // Tracker.init(): the frames' time starts over at 0 too
};

// A seed read and checked, not yet given to a tracker: a bad one raises before the tracker
// changes (a new size rescales it first, and the seed is in the new frame's pixels).
struct Seed {
  Where::Kind kind = Where::Nowhere;  // Nowhere, Point, Box or Mask
  Point2i point;
  Rect box;
  std::vector<std::uint8_t> mask;  // width × height, 255 on the object
};

// The one start among `starts` (each an object, a null handle when not given, and how to read
// it): a Where of kind Nowhere when none is given, a ValueError when several are.
Where one_of(std::initializer_list<Where> starts);
// `obj`, or a null handle (not given) when it is None, a keyword's default.
inline pybind11::handle given(const pybind11::handle& obj) {
  return obj.is_none() ? pybind11::handle() : obj;
}

// `obj` as a number: a TypeError naming `what` for anything else.
double number(const pybind11::handle& obj, const std::string& what);

// The seed `where` gives in a width × height frame: a ValueError for a point outside it, a box
// without area or outside it, a mask of another shape, empty or holding NaN, another count of
// numbers, or an array of another dimension; a TypeError for what are not numbers. A box is
// clipped to the frame.
Seed parse_seed(const Where& where, int width, int height);

}  // namespace projtrack::python
