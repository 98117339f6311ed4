#include "figures.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <string>

namespace projtrack::bench {

namespace {

const cv::Scalar kFill(255, 255, 0), kGrid(255, 0, 255), kBlock(255, 128, 64), kRay(0, 200, 0),
    kHit(0, 255, 255), kBox(0, 0, 255), kCentroid(0, 0, 255), kTruth(255, 255, 255),
    kSeed(0, 255, 255);

cv::Point px(Point2d p) {
  return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))};
}
cv::Point px(Point2i p) { return {p.x, p.y}; }

void tint(cv::Mat& img, const cv::Rect& r, const cv::Scalar& c) {
  cv::Mat roi = img(r & cv::Rect(0, 0, img.cols, img.rows));
  cv::addWeighted(roi, 0.5, cv::Mat(roi.size(), roi.type(), c), 0.5, 0, roi);
}

cv::Mat panel(const cv::Mat& base, Method method, const Features& f, const Trace& trace,
              int iteration, Point2d truth, const cv::Rect& focus, const std::string& label) {
  cv::Mat img = base.clone();
  for (const Trace::Run& r : trace.runs) {
    const cv::Rect run(r.first.x, r.first.y, r.last.x - r.first.x + 1, r.last.y - r.first.y + 1);
    if (method_info(method).trace == TraceKind::GridLines)
      img(run).setTo(kGrid);
    else
      tint(img, run, kFill);
  }
  for (const Trace::Block& b : trace.blocks) {
    if (b.iteration > iteration) continue;
    const cv::Rect r(b.rect.x, b.rect.y, b.rect.width, b.rect.height);
    tint(img, r, kBlock);
    cv::rectangle(img, r, kBlock, 1);
  }
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == iteration) cv::line(img, px(r.origin), px(r.hit), kRay, 1, cv::LINE_8);
  for (const Trace::Ray& r : trace.rays)
    if (r.iteration == iteration)
      cv::rectangle(img, cv::Rect(px(r.hit) - cv::Point(1, 1), cv::Size(3, 3)), kHit, cv::FILLED);
  const Point2d centroid = iteration <= static_cast<int>(trace.iterations.size())
                               ? trace.iterations[iteration - 1].centroid
                               : f.centroid;
  const Point2i from = iteration <= static_cast<int>(trace.iterations.size())
                           ? trace.iterations[iteration - 1].inner_point
                           : f.seed;
  if (iteration == f.iterations)
    cv::rectangle(img, cv::Rect(f.bbox.x, f.bbox.y, f.bbox.width, f.bbox.height), kBox, 1);
  cv::drawMarker(img, px(truth), kTruth, cv::MARKER_CROSS, 9, 1);
  cv::drawMarker(img, px(centroid), kCentroid, cv::MARKER_CROSS, 11, 2);
  cv::rectangle(img, cv::Rect(px(from) - cv::Point(2, 2), cv::Size(5, 5)), kSeed, cv::FILLED);
  cv::Mat out;
  cv::resize(img(focus), out, cv::Size(), 2, 2, cv::INTER_NEAREST);
  cv::putText(out, label, {8, 22}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
  return out;
}

}  // namespace

cv::Mat draw_figure(const cv::Mat& gray, const cv::Mat& edges, Method method, const Features& f,
                    const Trace& trace, Point2d true_centroid, const cv::Rect& focus) {
  cv::Mat base;
  cv::cvtColor(gray / 2, base, cv::COLOR_GRAY2BGR);
  base.setTo(cv::Scalar(255, 255, 255), edges);
  const cv::Rect crop = focus & cv::Rect(0, 0, gray.cols, gray.rows);
  std::string name(method_name(method));
  if (f.iterations <= 1) return panel(base, method, f, trace, 1, true_centroid, crop, name);
  cv::Mat first = panel(base, method, f, trace, 1, true_centroid, crop, name + ": iteration 1");
  cv::Mat last = panel(base, method, f, trace, f.iterations, true_centroid, crop,
                       name + ": iteration " + std::to_string(f.iterations));
  cv::Mat both;
  cv::hconcat(
      std::vector<cv::Mat>{first, cv::Mat(first.rows, 6, first.type(), cv::Scalar(40, 40, 40)),
                           last},
      both);
  return both;
}

}  // namespace projtrack::bench
