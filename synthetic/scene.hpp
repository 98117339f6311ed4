// Synthetic scenes, shared by the benchmark and the tests: rendered camera-like frames of a shaded
// sphere or a five-finger hand, their edges with deliberate miscalculations, and exact ground
// truth.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "projtrack/edge_detection.hpp"
#include "projtrack/geometry.hpp"

namespace projtrack::synthetic {

enum class Object { Sphere, Hand };

// The scene model's constants (bench/paper/main.cpp writes them into meta.json for the report).
struct SceneModel {
  static constexpr double kBlurSigma = 0.8;     // optical blur, px, at every resolution
  static constexpr double kNoiseSigma = 3.0;    // sensor noise, grey levels
  static constexpr int kGapRunMin = 1;          // a deliberate gap removes this many contour pixels
  static constexpr int kGapRunMax = 3;          // ... up to this many, in a row
  static constexpr double kSpeckShare = 0.004;  // spurious specks: this share of the interior
  static constexpr int kStrokes = 4;            // and this many short strokes
  // The mask's truth agrees with the independent counts when the area is within this share of
  // the supersampled one (and of π r² for the sphere) and the centroid within this many px.
  static constexpr double kTruthAreaTolerance = 0.01;
  static constexpr double kTruthAnalyticTolerance = 0.005;
  static constexpr double kTruthCentroidTolerance = 0.25;
};
const char* object_name(Object o);

struct SceneSpec {
  SceneSpec(int w = 640, int h = 480, Object o = Object::Sphere, double gaps = 0,
            bool specks = false, int inst = 0, double size = 1.0)
      : width(w),
        height(h),
        object(o),
        gap_rate(gaps),
        spurious(specks),
        instance(inst),
        scale(size) {}

  int width = 640, height = 480;
  Object object = Object::Sphere;
  double gap_rate = 0;    // fraction of the contour's edge pixels removed, in runs of 1–3 px
  bool spurious = false;  // spurious edge pixels and short segments inside the object
  int instance = 0;       // varies the position and the random gaps, noise and specks
  double scale = 1.0;     // object size: 1 = about 160 px across at 480 lines; 0.5 = a far object
  // For sequences (a moving object): where the object is (default: near the frame centre; it may
  // be partly or wholly outside the frame), a grey bar in front of everything, and a second,
  // smaller moving disc elsewhere.
  std::optional<Point2d> centre;
  std::optional<cv::Rect> occluder;
  std::optional<Point2d> distractor;
};

// A region of the object that seeds are drawn from (palm, each finger, thumb; or the sphere).
struct Part {
  std::string name;
  cv::Mat mask;  // CV_8U, 255 inside the part, eroded so seeds are well inside
};

struct Scene {
  SceneSpec spec;
  cv::Mat image;  // CV_8U gray frame: shading, a low-contrast stretch, blur, sensor noise
  cv::Mat mask;   // CV_8U, 255 on the object: pixel centres inside the analytic shape
  cv::Mat edges;  // CV_8U edge map: Canny of `image`, then the deliberate gaps and specks
  std::vector<Part> parts;

  double true_area = 0;   // mask pixel count (0 when the object is out of the frame)
  Point2d true_centroid;  // (-1, -1) when the object is out of the frame
  // Independent of the mask: a 4×4 supersampled count of the analytic shape, and for the
  // sphere the closed form π r².
  double supersampled_area = 0;
  Point2d supersampled_centroid;
  double analytic_area = 0;  // 0 when there is no closed form (the hand)

  int contour_pixels = 0;      // object boundary length, px
  int natural_gaps = 0;        // edge pixels added to close Canny's own breaks in the contour
  int gap_pixels_removed = 0;  // deliberate gaps
  int spurious_pixels = 0;

  ImageView gray_view() const { return ImageView(image.data, image.cols, image.rows, image.step); }
  ImageView edge_view() const { return ImageView(edges.data, edges.cols, edges.rows, edges.step); }
};

Scene make_scene(const SceneSpec& spec, const EdgeParams& edge_params);

// True when the mask's area and centroid agree with the independent counts (SceneModel's
// tolerances); `why` says what disagrees.
bool truth_is_consistent(const Scene& s, std::string* why);

struct Seed {
  Point2i p;
  std::string part;
};
// About `total` seeds, drawn uniformly from every part in equal numbers (so each finger gets its
// share, not just the palm).
std::vector<Seed> sample_seeds(const Scene& s, int total, std::mt19937& rng);

}  // namespace projtrack::synthetic
