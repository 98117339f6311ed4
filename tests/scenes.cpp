#include "scenes.hpp"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>

#include "projtrack/edge_detection.hpp"

namespace projtrack::test {

Scene scene_from_mask(std::string name, const cv::Mat& inside) {
  Scene s;
  s.name = std::move(name);
  s.inside = inside.clone();
  // Object pixels with a 4-neighbour outside (or on the frame border): every 4-connected path
  // from the interior to the outside crosses one, so the contour is closed for a 4-connected fill.
  cv::Mat eroded;
  const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3));
  cv::erode(inside, eroded, cross, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  s.edges = inside - eroded;
  s.interior = eroded;
  s.area = cv::countNonZero(s.interior);
  const cv::Moments m = cv::moments(s.interior, true);
  s.centroid = {m.m10 / m.m00, m.m01 / m.m00};
  return s;
}

Scene disc_scene() {
  cv::Mat inside = cv::Mat::zeros(180, 200, CV_8U);
  cv::circle(inside, {100, 90}, 40, 255, cv::FILLED, cv::LINE_8);
  return scene_from_mask("disc", inside);
}

Scene square_scene() {
  cv::Mat inside = cv::Mat::zeros(180, 200, CV_8U);
  cv::rectangle(inside, cv::Rect(70, 60, 61, 61), 255, cv::FILLED);
  return scene_from_mask("square", inside);
}

Scene ring_scene() {
  cv::Mat inside = cv::Mat::zeros(180, 200, CV_8U);
  cv::circle(inside, {100, 90}, 50, 255, cv::FILLED, cv::LINE_8);
  cv::circle(inside, {100, 90}, 20, 0, cv::FILLED, cv::LINE_8);
  return scene_from_mask("ring", inside);
}

Scene hand_scene() {
  cv::Mat inside = cv::Mat::zeros(240, 240, CV_8U);
  cv::ellipse(inside, {120, 160}, {42, 40}, 0, 0, 360, 255, cv::FILLED, cv::LINE_8);
  const int finger_x[4] = {90, 110, 130, 150};  // 12 px wide, 8 px apart
  const int finger_top[4] = {70, 52, 56, 78};
  for (int i = 0; i < 4; ++i)
    cv::rectangle(inside, cv::Rect(finger_x[i] - 6, finger_top[i], 12, 140 - finger_top[i]), 255,
                  cv::FILLED);
  cv::line(inside, {88, 170}, {45, 128}, 255, 13, cv::LINE_8);  // the thumb
  return scene_from_mask("hand", inside);
}

std::vector<Scene> all_scenes() {
  return {disc_scene(), square_scene(), ring_scene(), hand_scene()};
}

Point2i open_gap_right(Scene& s, int x_start, int y) {
  for (int x = x_start; x + 1 < s.edges.cols; ++x) {
    if (s.edges.at<std::uint8_t>(y, x) == 0) continue;
    const bool interior_left = s.interior.at<std::uint8_t>(y, x - 1) != 0;
    const bool outside_right = s.inside.at<std::uint8_t>(y, x + 1) == 0;
    if (!interior_left || !outside_right)
      throw std::runtime_error("no straight 1-px gap on this row of " + s.name);
    s.edges.at<std::uint8_t>(y, x) = 0;
    return {x, y};
  }
  throw std::runtime_error("no contour on this row of " + s.name);
}

std::vector<Point2i> interior_points(const Scene& s, int step) {
  std::vector<Point2i> points;
  for (int y = step / 2; y < s.interior.rows; y += step)
    for (int x = step / 2; x < s.interior.cols; x += step)
      if (s.is_interior({x, y})) points.push_back({x, y});
  return points;
}

GrayFrame with_edges(cv::Mat gray) {
  GrayFrame f;
  f.gray = std::move(gray);
  EdgeMap map;
  const ImageView e = map.detect(f.g(), {});
  f.edges =
      cv::Mat(f.gray.rows, f.gray.cols, CV_8U, const_cast<std::uint8_t*>(e.data), e.stride).clone();
  return f;
}

GrayFrame disc_frame(int cx, int cy, int r, int w, int h) {
  cv::Mat gray(h, w, CV_8U, cv::Scalar(40));
  if (r > 0) cv::circle(gray, {cx, cy}, r, cv::Scalar(210), cv::FILLED, cv::LINE_AA);
  return with_edges(gray);
}

cv::Mat random_i420(int w, int h, int max) {
  cv::Mat bgr(h, w, CV_8UC3), i420;
  cv::randu(bgr, cv::Scalar::all(0), cv::Scalar::all(max));
  cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  return i420;
}

ColorView i420_view(const cv::Mat& i420, int w, int h) {
  ColorView c;
  c.luma = ImageView(i420.data, w, h, w);
  c.chroma = {i420.data + w * h, i420.data + w * h + (w / 2) * (h / 2), w / 2, 1, 1, 1};
  return c;
}

}  // namespace projtrack::test
