// Edge maps the tests draw themselves, with ground truth counted independently of the estimators.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projtrack/color_view.hpp"
#include "projtrack/geometry.hpp"
#include "projtrack/image_view.hpp"

namespace projtrack::test {

struct Scene {
  std::string name;
  cv::Mat inside;    // CV_8U, 255 on the object
  cv::Mat edges;     // CV_8U, 255 on the contour: object pixels with a 4-neighbour outside
  cv::Mat interior;  // CV_8U, 255 on the object's free pixels (inside and not contour)
  double area = 0;   // interior pixel count
  Point2d centroid;  // mean interior pixel

  ImageView edge_view() const { return ImageView(edges.data, edges.cols, edges.rows, edges.step); }
  bool is_interior(Point2i p) const { return interior.at<std::uint8_t>(p.y, p.x) != 0; }
};

// Builds edges, interior and ground truth from an object mask.
Scene scene_from_mask(std::string name, const cv::Mat& inside);

Scene disc_scene();    // radius 40 in 200×180
Scene square_scene();  // 61×61, axis-aligned, in 200×180
Scene ring_scene();    // radii 20 and 50 in 200×180: the hole is not part of the object
Scene hand_scene();    // palm, four fingers and a thumb in 240×240; 8 px between fingers
std::vector<Scene> all_scenes();

// Removes one contour pixel so that a 4-connected path leads from the interior to the outside:
// the first such pixel met walking right along row `y` from the interior point (x_start, y).
// Returns the pixel opened.
Point2i open_gap_right(Scene& s, int x_start, int y);

// Interior pixels on a regular lattice of the given step (seeds to start estimates from).
std::vector<Point2i> interior_points(const Scene& s, int step);

// A gray frame and its edges as the tracker's default edge detection finds them.
struct GrayFrame {
  cv::Mat gray, edges;  // CV_8U
  ImageView g() const { return ImageView(gray.data, gray.cols, gray.rows, gray.step); }
  ImageView e() const { return ImageView(edges.data, edges.cols, edges.rows, edges.step); }
};
GrayFrame with_edges(cv::Mat gray);
// A bright disc (radius `r`, none for 0) centred at (cx, cy) on a dark `w` × `h` frame.
GrayFrame disc_frame(int cx, int cy, int r, int w = 320, int h = 240);

// A `w` × `h` frame of random BGR colours (channels in [0, max)) converted to I420.
cv::Mat random_i420(int w, int h, int max);

// The colour view of a contiguous I420 frame of `w` × `h` (as cv::cvtColor writes it).
ColorView i420_view(const cv::Mat& i420, int w, int h);

}  // namespace projtrack::test
