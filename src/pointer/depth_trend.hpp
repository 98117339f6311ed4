// The slow trend of a track's depth: where its depth would be now without a gesture.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>

namespace projtrack {

// A line in time: value(t) = level + slope · (t − t_mid). `noise` is the samples' scatter about
// it (1.4826 × their median absolute deviation: σ for Gaussian noise); NaN when not measured.
struct TrendLine {
  double level = 0, slope = 0, t_mid = 0, noise = 0;
  double at(double t) const { return level + slope * (t - t_mid); }
};

// The samples (t, ln depth) of a track at rest, newest last, kept for `window` + `guard` seconds.
class DepthTrend {
 public:
  void add(double t, double v, double window, double guard);
  void clear() { samples_.clear(); }
  std::size_t size() const { return samples_.size(); }
  // The line through the samples older than `guard` s before `t` (least squares, then again
  // without those farther than 3 noise from it: a leak's frame does not tilt it); none while
  // they span less than `settle` s or are fewer than five.
  std::optional<TrendLine> fit(double t, double guard, double settle) const;
  // A level through the median of the samples, with the given slope, from as few as three
  // samples (just after a gesture, before a line can be fitted); none with fewer. Its noise is
  // not measured (NaN).
  std::optional<TrendLine> level(double slope) const;
  // The median of the newest three samples' values (none: NaN).
  double recent() const;

 private:
  struct Sample {
    double t, v;
  };
  std::deque<Sample> samples_;
};

}  // namespace projtrack
