// Follows one object from frame to frame: the inner point between frames, one estimator per method.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "estimator.hpp"

namespace projtrack {

class Tracker {
 public:
  // Starts (or restarts) tracking from `p`.
  void seed(Point2i p) { inner_ = p; }
  // Forgets the object: the next track() reports Status::NoInnerPoint until seeded.
  void reset() { inner_.reset(); }
  const std::optional<Point2i>& inner_point() const { return inner_; }

  // Estimates the features around the current inner point with method `m`; when they are valid,
  // the inner point moves to the estimate's updated one for the next frame (otherwise it stays).
  Features track(const ImageView& edges, Method m, const Params& params, Trace* trace = nullptr);

 private:
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators_;  // made on first use
  std::optional<Point2i> inner_;
};

}  // namespace projtrack
