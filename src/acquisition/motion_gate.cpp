#include "acquisition/motion_gate.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace projtrack {

namespace {

constexpr int kGrid = 8;  // cells a side
constexpr std::size_t kCells = kGrid * kGrid;
constexpr double kStandsOut = 2;  // a part that moves: its cell's changes over the median cell's

}  // namespace

bool changed_evenly(const MotionDetector::Motion& moved, int width, int height) {
  if (width <= 0 || height <= 0) return false;
  // The cells' first columns and rows; the samples come row by row, so a sample's cell is found
  // by stepping on from the last one's (no division per sample).
  std::array<long long, kGrid + 1> xs{}, ys{};
  for (int k = 0; k <= kGrid; ++k) {
    xs[static_cast<std::size_t>(k)] = (static_cast<long long>(width) * k + kGrid - 1) / kGrid;
    ys[static_cast<std::size_t>(k)] = (static_cast<long long>(height) * k + kGrid - 1) / kGrid;
  }
  std::array<int, kCells> count{};
  int cx = 0, cy = 0, last_x = -1, last_y = -1;
  for (const Point2i& q : moved.points) {
    if (q.x < 0 || q.y < 0 || q.x >= width || q.y >= height) continue;
    if (q.y != last_y || q.x < last_x) {
      cx = 0;
      if (q.y < last_y) cy = 0;
    }
    while (q.y >= ys[static_cast<std::size_t>(cy) + 1]) ++cy;
    while (q.x >= xs[static_cast<std::size_t>(cx) + 1]) ++cx;
    last_x = q.x;
    last_y = q.y;
    ++count[static_cast<std::size_t>(cy * kGrid + cx)];
  }
  std::array<int, kCells> sorted = count;
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
