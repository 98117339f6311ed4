#include "acquisition/motion_gate.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace projtrack {

namespace {

constexpr int kGrid = 8;          // cells a side
constexpr double kStandsOut = 2;  // a part that moves: its cell's changes over the median cell's

}  // namespace

bool changed_evenly(const MotionDetector::Motion& moved, int width, int height) {
  if (width <= 0 || height <= 0) return false;
  std::array<int, kGrid * kGrid> count{};
  for (const Point2i& q : moved.points) {
    const int cx = static_cast<int>(static_cast<long long>(q.x) * kGrid / width);
    const int cy = static_cast<int>(static_cast<long long>(q.y) * kGrid / height);
    if (cx >= 0 && cy >= 0 && cx < kGrid && cy < kGrid)
      ++count[static_cast<std::size_t>(cy * kGrid + cx)];
  }
  std::array<int, kGrid* kGrid> sorted = count;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const int median = sorted[sorted.size() / 2];
  const int least = *std::min_element(count.begin(), count.end());
  const int most = *std::max_element(count.begin(), count.end());
  return least > 0 && most <= kStandsOut * median;
}

std::string wait_for_motion(MotionDetector& detector, const ImageView& gray,
                            const MotionDetector::Params& p, double min_motion,
                            MotionDetector::Motion& moved) {
  if (!detector.update(gray, p, moved)) return "waiting for a second frame to compare";
  if (moved.fraction >= min_motion) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "waiting for motion (%.2g %% of the frame changed)",
                100 * moved.fraction);
  return buf;
}

}  // namespace projtrack
