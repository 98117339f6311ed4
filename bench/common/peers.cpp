#include "peers.hpp"

#include <opencv2/imgproc.hpp>

#include "projtrack/estimator.hpp"  // border_status: the status the estimators give

namespace projtrack::bench {

Features OpenCvFloodFill::estimate(const cv::Mat& edges, Point2i seed) {
  Features f;
  f.seed = f.inner_point = seed;
  edges.copyTo(work_);
  cv::Rect r;
  const int area = cv::floodFill(work_, cv::Point(seed.x, seed.y), 128, &r, 0, 0, 4);
  const cv::Moments m = cv::moments(work_(r) == 128, true);
  f.area = area;
  f.centroid = {r.x + m.m10 / m.m00, r.y + m.m01 / m.m00};
  f.bbox = {r.x, r.y, r.width, r.height};
  f.iterations = 1;
  f.status = border_status(f.bbox, edges.cols, edges.rows);
  return f;
}

Features OpenCvComponents::estimate(const cv::Mat& edges, Point2i seed) {
  Features f;
  f.seed = f.inner_point = seed;
  cv::compare(edges, 0, free_, cv::CMP_EQ);
  cv::connectedComponentsWithStats(free_, labels_, stats_, centroids_, 4, CV_32S);
  const int label = labels_.at<int>(seed.y, seed.x);
  if (label == 0) {
    f.status = EstimateStatus::InnerPointOnEdge;
    return f;
  }
  f.area = stats_.at<int>(label, cv::CC_STAT_AREA);
  f.centroid = {centroids_.at<double>(label, 0), centroids_.at<double>(label, 1)};
  f.bbox = {stats_.at<int>(label, cv::CC_STAT_LEFT), stats_.at<int>(label, cv::CC_STAT_TOP),
            stats_.at<int>(label, cv::CC_STAT_WIDTH), stats_.at<int>(label, cv::CC_STAT_HEIGHT)};
  f.iterations = 1;
  f.status = border_status(f.bbox, edges.cols, edges.rows);
  return f;
}

}  // namespace projtrack::bench
