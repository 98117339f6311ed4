// A budget of work for one frame, counted in work and never in time, so that what a frame comes
// to stays deterministic; and a flag that stops the work at once (a pipeline shutting down).
//
// The estimators count their work as they go (Work, rays.hpp) and poll the budget at coarse
// checkpoints: per ray, per fill run, per grid line, per iteration; edge detection every 16 rows
// of Canny and between filter passes; the tracker per seed and per piece of a silhouette; the
// flow model before each of its stages (the work images, a frame's motion and cut, each stage of
// a start's cut, the searches), which pay what they will do before they run. Never per pixel.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>

namespace projtrack {

// The unit of work is about what one pixel of a fill costs (reading it and marking it as part of
// a run). The other kinds of work are weighted by what each costs beside it, so that a budget of
// units bounds the time of every method alike: tools/work_cost.cpp times every method and Canny on
// the adversarial content at 1080p, where a unit costs each of them within a few times of the
// others (a pixel visited costs them many times apart). Canny's own weights are in canny.cpp.
inline constexpr std::uint64_t kCostPerRayStep = 4;      // a ray's or a walk's step: a dependent,
                                                         // branchy read, never vectorised
inline constexpr std::uint64_t kCostPerRay = 16;         // a ray's start and end, beside its steps
inline constexpr std::uint64_t kCostPerRun = 16;         // a fill's run or grid line: queued,
                                                         // taken, extended, beside its pixels
inline constexpr std::uint64_t kCostPerCrossing = 4;     // a grid line queued where a run
                                                         // crosses it (every pixel at grid 1)
inline constexpr std::uint64_t kCostPerColumnPixel = 4;  // a pixel of a vertical run: a row
                                                         // apart from the last, a cache line each
inline constexpr std::uint64_t kScannedPixelsPerCost = 4;  // pixels a vectorised loop reads or
                                                           // marks per unit
inline constexpr std::uint64_t kClearedBytesPerCost = 32;  // bytes cleared (memset) per unit

// What clearing `bytes` bytes costs.
inline std::uint64_t clearing_cost(std::uint64_t bytes) { return bytes / kClearedBytesPerCost; }
// What clearing a width × height rectangle of a byte mask costs.
inline std::uint64_t clearing_cost(int width, int height) {
  return width <= 0 || height <= 0 ? 0 : clearing_cost(static_cast<std::uint64_t>(width) * height);
}

// How far a width × height frame's work may pass its limit: the work between two checkpoints, at
// most 16 rows of Canny at its costliest, one run of gap-tolerant filling across the frame with
// its band and contour-end tests, one triangle of recursive ray-casting's area, and one search for
// a free pixel around an inner point. (TrackResult::work <= work_limit + this; tested.)
inline std::uint64_t overshoot_bound(int width, int height) {
  const std::uint64_t w = static_cast<std::uint64_t>(std::max(width, 0));
  const std::uint64_t h = static_cast<std::uint64_t>(std::max(height, 0));
  return 16 * w * 13 + 256 * std::max(w, h) + w * h / kScannedPixelsPerCost + 2 * h + 129 * 129;
}

class WorkBudget {
 public:
  static constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();

  // Unlimited and never stopped.
  WorkBudget() = default;
  // At most `limit` units; `stop` (may be null), when set by another thread, stops the work at the
  // next checkpoint.
  explicit WorkBudget(std::uint64_t limit, const std::atomic<bool>* stop = nullptr)
      : limit_(limit), stop_(stop) {}

  std::uint64_t limit() const { return limit_; }
  std::uint64_t spent() const { return spent_; }
  // Units left before the limit (0 once it is passed).
  std::uint64_t left() const { return spent_ >= limit_ ? 0 : limit_ - spent_; }
  bool unlimited() const { return limit_ == kUnlimited; }

  // The stop flag is set.
  bool interrupted() const { return stop_ && stop_->load(std::memory_order_relaxed); }
  // A checkpoint found the budget spent, or an estimate was refused because it could not fit in
  // what was left: the budget stays run out (and every later checkpoint says stop).
  bool ran_out() const { return ran_out_; }

  // The checkpoint: true when the work must stop, because `pending` more units (done since the
  // last spend()) would pass the limit, the budget ran out before, or the stop flag is set.
  bool exhausted(std::uint64_t pending = 0) {
    if (!ran_out_ && (spent_ > limit_ || pending > limit_ - spent_)) ran_out_ = true;
    return ran_out_ || interrupted();
  }
  // Takes `units` of work done from the budget.
  void spend(std::uint64_t units) {
    spent_ = units > kUnlimited - spent_ ? kUnlimited : spent_ + units;
  }

 private:
  std::uint64_t limit_ = kUnlimited;
  std::uint64_t spent_ = 0;
  bool ran_out_ = false;
  const std::atomic<bool>* stop_ = nullptr;
};

}  // namespace projtrack
