// The slow trend of a track's depth: where its depth would be now without a gesture.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace projtrack {

// A line in time: value(t) = level + slope · (t − t_mid). `noise` is the samples' scatter about
// it (1.4826 × their median absolute deviation: σ for Gaussian noise); NaN when not measured.
struct TrendLine {
  double level = 0, slope = 0, t_mid = 0, noise = 0;
  double at(double t) const { return level + slope * (t - t_mid); }
};

struct TimedValue {
  double t, v;
};

// The median of `v` (the mean of the middle two for an even count), reordering it; NaN when
// empty.
double median(std::vector<double>& v);
// The least-squares line through the points (at least one; one instant gives a flat line), its
// noise not measured (NaN).
TrendLine least_squares(const std::vector<TimedValue>& pts);
// The line of the given slope through the median of the points brought along it to their median
// time (at least one point): a level that one outlier does not move. Its noise: NaN. `scratch`
// is working space (kept by the caller, so that a frame allocates nothing).
TrendLine median_line(const std::vector<TimedValue>& pts, double slope,
                      std::vector<double>& scratch);

// The samples (t, ln depth) of a track at rest, oldest first, kept for `window` + `guard`
// seconds. Its working space is kept between frames: once warm, no frame allocates.
class DepthTrend {
 public:
  void add(double t, double v, double window, double guard);
  void clear() { samples_.clear(); }
  std::size_t size() const { return samples_.size(); }
  // The line through the samples older than `guard` s before `t` (least squares, then again
  // without those farther than 3 noise from it: a leak's frame does not tilt it); none while
  // they span less than `settle` s or are fewer than five.
  std::optional<TrendLine> fit(double t, double guard, double settle);
  // A level through the median of the samples, with the given slope, from as few as three
  // samples (just after a gesture, before a line can be fitted); none with fewer. Its noise is
  // not measured (NaN).
  std::optional<TrendLine> level(double slope);
  // The median of the newest three samples' values (none: NaN).
  double recent();

 private:
  // 1.4826 × the median absolute residual of `pts` about `line`: σ for Gaussian scatter.
  double scatter(const std::vector<TimedValue>& pts, const TrendLine& line);

  std::vector<TimedValue> samples_, pts_, kept_;
  std::vector<double> scratch_;
};

}  // namespace projtrack
