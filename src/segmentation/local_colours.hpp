// The object's colours against its surroundings' near each part of it: the silhouette's box cut
// into a grid of cells, each with its own pair of colour histograms. A camel and the sand it
// walks on share their colours over the frame, yet near its hump the sand is lighter than the
// hump, and near its legs the legs are darker than that sand: what a global mixture cannot tell
// apart, a cell can. Learned from one frame's silhouette and its ring, read on the next frame
// with the grid moved by the object's motion.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace projtrack {

class LocalColours {
 public:
  static constexpr int kLevels = 8;  // per channel: a cell holds few pixels
  static constexpr int kBins = kLevels * kLevels * kLevels;

  // Learns every cell of a `cells` × `cells` grid over `box` (a rectangle of `bgr`, CV_8UC3):
  // the object where `inside` is set, its surroundings where only `around` is (both CV_8U, of
  // the box's size).
  void learn(const cv::Mat& bgr, const cv::Rect& box, const cv::Mat& inside, const cv::Mat& around,
             int cells);
  // Adds to `log_odds` (CV_32F, the size of `where`, a rectangle of `bgr`) `weight` × each
  // pixel's log-likelihood ratio of object against surroundings in its cell, the grid moved by
  // `moved` work px; at most ±kMostNats before the weight (a cell learns from few pixels).
  void add_evidence(const cv::Mat& bgr, const cv::Rect& where, cv::Point2f moved, double weight,
                    cv::Mat& log_odds);
  bool learned() const { return cells_ > 0; }
  void forget() { cells_ = 0; }
  // The work frame is now rx × ry times as large: the grid follows.
  void rescale(double rx, double ry);

  static constexpr float kMostNats = 3;

 private:
  int cells_ = 0;
  cv::Rect box_;
  std::vector<float> ratio_;  // the model: the log-likelihood ratio per cell and bin
  // Buffers of learn(): each cell's counts per bin and in all.
  std::vector<float> object_, surroundings_, object_total_, surroundings_total_;
  std::vector<int> column_;  // a buffer: each column's cell
};

}  // namespace projtrack
