#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace projtrack::synthetic {

namespace {

// The object as a union of analytic primitives, so membership is exact at any sample point.
struct Primitive {
  enum Kind { Ellipse, Capsule } kind;
  double x0, y0, x1, y1;  // ellipse: centre and semi-axes (x1, y1); capsule: segment ends
  double r;               // capsule radius
  std::string part;

  bool inside(double x, double y) const {
    if (kind == Ellipse) {
      const double u = (x - x0) / x1, v = (y - y0) / y1;
      return u * u + v * v <= 1.0;
    }
    const double vx = x1 - x0, vy = y1 - y0, px = x - x0, py = y - y0;
    const double t = std::clamp((px * vx + py * vy) / (vx * vx + vy * vy), 0.0, 1.0);
    const double dx = px - t * vx, dy = py - t * vy;
    return dx * dx + dy * dy <= r * r;
  }
  cv::Rect2d bounds() const {
    if (kind == Ellipse) return {x0 - x1, y0 - y1, 2 * x1, 2 * y1};
    return {std::min(x0, x1) - r, std::min(y0, y1) - r, std::abs(x1 - x0) + 2 * r,
            std::abs(y1 - y0) + 2 * r};
  }
};

struct Shape {
  std::vector<Primitive> primitives;
  bool inside(double x, double y) const {
    for (const Primitive& p : primitives)
      if (p.inside(x, y)) return true;
    return false;
  }
  cv::Rect bounds(int width, int height) const {
    cv::Rect2d b = primitives.front().bounds();
    for (const Primitive& p : primitives) b |= p.bounds();
    const cv::Rect r(static_cast<int>(std::floor(b.x)) - 2, static_cast<int>(std::floor(b.y)) - 2,
                     static_cast<int>(std::ceil(b.width)) + 5,
                     static_cast<int>(std::ceil(b.height)) + 5);
    return r & cv::Rect(0, 0, width, height);
  }
};

// Sizes are those of a 640×480 frame, scaled by s = height / 480.
Shape make_shape(Object object, double cx, double cy, double s) {
  Shape shape;
  if (object == Object::Sphere) {
    shape.primitives.push_back({Primitive::Ellipse, cx, cy, 80 * s, 80 * s, 0, "sphere"});
    return shape;
  }
  shape.primitives.push_back({Primitive::Ellipse, cx, cy + 20 * s, 62 * s, 56 * s, 0, "palm"});
  // Fingers 16 px wide, 4 px apart at the base and splaying a little toward the tips.
  const double base_x[4] = {-30, -10, 10, 30}, top_y[4] = {-95, -112, -106, -84};
  for (int i = 0; i < 4; ++i) {
    shape.primitives.push_back({Primitive::Capsule, cx + base_x[i] * s, cy - 10 * s,
                                cx + base_x[i] * 1.2 * s, cy + top_y[i] * s, 8 * s,
                                "finger" + std::to_string(i + 1)});
  }
  shape.primitives.push_back(
      {Primitive::Capsule, cx - 50 * s, cy + 30 * s, cx - 100 * s, cy - 18 * s, 10 * s, "thumb"});
  return shape;
}

double background(Object object, double x, double y, int width, int height, double s) {
  const double texture = 6 * std::sin(x / (37 * s)) * std::sin(y / (29 * s));
  if (object == Object::Sphere) return 30 + 40 * x / width + texture;  // brighter on the right
  // Dark overall, with a bright stretch on the left where the thumb meets it at low contrast.
  const double stretch = std::exp(-std::pow((x / width - 0.22) / 0.12, 2));
  return 70 + 10 * y / height + 65 * stretch + texture;
}

double object_intensity(Object object, const Shape& shape, double x, double y, double s) {
  if (object == Object::Sphere) {
    // A Lambertian sphere lit from the upper left: its dark limb (lower right) lies against the
    // bright side of the background, a low-contrast stretch.
    const Primitive& c = shape.primitives.front();
    const double nx = (x - c.x0) / c.x1, ny = (y - c.y0) / c.y1;
    const double nz = std::sqrt(std::max(0.0, 1 - nx * nx - ny * ny));
    const double lx = -0.5, ly = -0.6, lz = 0.62, ln = std::sqrt(lx * lx + ly * ly + lz * lz);
    const double lambert = std::max(0.0, (nx * lx + ny * ly + nz * lz) / ln);
    return 55 + 165 * std::max(0.35, lambert);
  }
  return 178 + 12 * (y - shape.primitives.front().y0) / (100 * s);  // evenly coloured, soft light
}

}  // namespace

const char* object_name(Object o) { return o == Object::Sphere ? "sphere" : "hand"; }

Scene make_scene(const SceneSpec& spec, const EdgeParams& edge_params) {
  Scene sc;
  sc.spec = spec;
  const int w = spec.width, h = spec.height;
  const double s = h / 480.0;
  std::mt19937 rng(1000 * spec.instance + static_cast<int>(spec.object) * 7 +
                   static_cast<int>(spec.gap_rate * 1000) + (spec.spurious ? 500 : 0) + w +
                   static_cast<int>(spec.scale * 100));
  std::uniform_real_distribution<double> jitter(-20 * s, 20 * s);
  const double jx = jitter(rng), jy = jitter(rng);
  const double cx = spec.centre ? spec.centre->x : w / 2.0 + jx;
  const double cy = spec.centre ? spec.centre->y : h / 2.0 + 10 * s + jy;
  const Shape shape = make_shape(spec.object, cx, cy, s * spec.scale);
  const cv::Rect box = shape.bounds(w, h);

  // Exact mask and its truth; a supersampled count as the independent check.
  sc.mask = cv::Mat::zeros(h, w, CV_8U);
  double sum_x = 0, sum_y = 0, n = 0, ss_x = 0, ss_y = 0, ss_n = 0;
  for (int y = box.y; y < box.br().y; ++y) {
    for (int x = box.x; x < box.br().x; ++x) {
      if (shape.inside(x, y)) {
        sc.mask.at<std::uint8_t>(y, x) = 255;
        sum_x += x, sum_y += y, n += 1;
      }
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const double sx = x - 0.375 + 0.25 * i, sy = y - 0.375 + 0.25 * j;
          if (shape.inside(sx, sy)) ss_x += sx, ss_y += sy, ss_n += 1;
        }
    }
  }
  if (spec.occluder) {
    // What the camera sees of the object: the bar hides part of it.
    const cv::Rect bar = *spec.occluder & cv::Rect(0, 0, w, h);
    for (int y = bar.y; y < bar.br().y; ++y)
      for (int x = bar.x; x < bar.br().x; ++x)
        if (sc.mask.at<std::uint8_t>(y, x)) {
          sc.mask.at<std::uint8_t>(y, x) = 0;
          sum_x -= x, sum_y -= y, n -= 1;
        }
  }
  sc.true_area = n;
  sc.true_centroid = n > 0 ? Point2d{sum_x / n, sum_y / n} : Point2d{-1, -1};
  sc.supersampled_area = ss_n / 16.0;
  sc.supersampled_centroid = ss_n > 0 ? Point2d{ss_x / ss_n, ss_y / ss_n} : Point2d{-1, -1};
  if (spec.object == Object::Sphere) {
    const double r = shape.primitives.front().x1;
    sc.analytic_area = M_PI * r * r;
  }

  // The camera's view: shading, optical blur, sensor noise.
  cv::Mat img(h, w, CV_32F);
  for (int y = 0; y < h; ++y) {
    float* row = img.ptr<float>(y);
    const std::uint8_t* m = sc.mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x)
      row[x] = static_cast<float>(m[x] ? object_intensity(spec.object, shape, x, y, s)
                                       : background(spec.object, x, y, w, h, s));
  }
  if (spec.distractor)
    cv::circle(
        img, cv::Point(static_cast<int>(spec.distractor->x), static_cast<int>(spec.distractor->y)),
        static_cast<int>(18 * s), cv::Scalar(215), cv::FILLED, cv::LINE_AA);
  if (spec.occluder) cv::rectangle(img, *spec.occluder, cv::Scalar(128), cv::FILLED);
  cv::GaussianBlur(img, img, cv::Size(),
                   SceneModel::kBlurSigma);  // per pixel: a sharper sensor at higher resolution
  cv::Mat noise(h, w, CV_32F);
  cv::RNG cvrng(rng());
  cvrng.fill(noise, cv::RNG::NORMAL, 0, SceneModel::kNoiseSigma);
  img += noise;
  img.convertTo(sc.image, CV_8U);

  EdgeMap edge_map;
  const ImageView gray(sc.image.data, w, h, static_cast<std::ptrdiff_t>(sc.image.step));
  const ImageView e = edge_map.detect(gray, edge_params);
  sc.edges = cv::Mat(h, w, CV_8U, const_cast<std::uint8_t*>(e.data), e.stride).clone();

  // Boundary pixels: object pixels with a 4-neighbour outside.
  cv::Mat eroded;
  const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, {3, 3});
  cv::erode(sc.mask, eroded, cross);
  sc.contour_pixels = cv::countNonZero(sc.mask - eroded);

  // Canny itself breaks the contour now and then (sharp concave corners, where non-maximum
  // suppression thins two edges meeting at an angle). Close those breaks: fill from inside the
  // object and, wherever the fill steps out, make that first outside pixel an edge. So the
  // deliberate gaps below are the only miscalculations of the contour.
  cv::Mat inner;
  cv::erode(sc.mask, inner, cross, cv::Point(-1, -1), 2);
  std::vector<cv::Point> starts;
  cv::findNonZero(inner, starts);
  cv::Mat work, filled, crossing, inside_filled;
  for (int round = 0; round < 100 && !starts.empty(); ++round) {
    sc.edges.copyTo(work);
    for (std::size_t i = 0; i < starts.size(); i += std::max<std::size_t>(1, starts.size() / 16))
      if (work.at<std::uint8_t>(starts[i]) == 0)
        cv::floodFill(work, starts[i], 128, nullptr, 0, 0, 4);
    filled = work == 128;
    cv::dilate(filled & sc.mask, inside_filled, cross);
    crossing = inside_filled & filled & ~sc.mask;
    const int n = cv::countNonZero(crossing);
    if (n == 0) break;
    sc.edges.setTo(255, crossing);
    sc.natural_gaps += n;
  }

  // Deliberate gaps: remove 1–3 consecutive edge pixels of the object's contour line, at places
  // spread at random, until gap_rate of the contour is missing.
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(sc.mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  if (contours.empty()) return sc;  // the object is out of the frame
  const auto& contour =
      *std::max_element(contours.begin(), contours.end(),
                        [](const auto& a, const auto& b) { return a.size() < b.size(); });
  const auto counterpart = [&](cv::Point p) -> cv::Point {
    cv::Point best(-1, -1);
    int best_d2 = 1 << 30;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const cv::Point q(p.x + dx, p.y + dy);
        if (q.x < 0 || q.y < 0 || q.x >= w || q.y >= h || !sc.edges.at<std::uint8_t>(q)) continue;
        if (dx * dx + dy * dy < best_d2) best_d2 = dx * dx + dy * dy, best = q;
      }
    return best;
  };
  const int target = static_cast<int>(std::lround(spec.gap_rate * contour.size()));
  std::uniform_int_distribution<std::size_t> start(0, contour.size() - 1);
  std::uniform_int_distribution<int> length(SceneModel::kGapRunMin, SceneModel::kGapRunMax);
  for (int tries = 0; sc.gap_pixels_removed < target && tries < 100000; ++tries) {
    const std::size_t i0 = start(rng);
    const int len = std::min(length(rng), target - sc.gap_pixels_removed);
    int removed = 0;
    for (std::size_t k = 0; k < 4u * len && removed < len; ++k) {
      const cv::Point q = counterpart(contour[(i0 + k) % contour.size()]);
      if (q.x < 0) continue;
      sc.edges.at<std::uint8_t>(q) = 0;
      ++removed;
    }
    sc.gap_pixels_removed += removed;
  }

  // Seed regions: each primitive's own pixels, well inside the object.
  cv::Mat interior;
  const int margin = std::max(3, static_cast<int>(std::lround(2 * s)));
  cv::erode(sc.mask, interior,
            cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * margin + 1, 2 * margin + 1}));
  for (std::size_t k = 0; k < shape.primitives.size(); ++k) {
    Part part{shape.primitives[k].part, cv::Mat::zeros(h, w, CV_8U)};
    for (int y = box.y; y < box.br().y; ++y)
      for (int x = box.x; x < box.br().x; ++x) {
        bool own = shape.primitives[k].inside(x, y);
        // Fingers and the thumb exclude the palm, so their seeds really are in them.
        if (own && k > 0 && shape.primitives[0].inside(x, y)) own = false;
        if (own && interior.at<std::uint8_t>(y, x)) part.mask.at<std::uint8_t>(y, x) = 255;
      }
    sc.parts.push_back(std::move(part));
  }

  // Spurious edges inside the object: isolated specks and short strokes (highlights, prints).
  if (spec.spurious) {
    std::vector<cv::Point> inside;
    cv::findNonZero(interior, inside);
    std::uniform_int_distribution<std::size_t> pick(0, inside.size() - 1);
    const int specks = static_cast<int>(SceneModel::kSpeckShare * inside.size());
    for (int i = 0; i < specks; ++i) sc.edges.at<std::uint8_t>(inside[pick(rng)]) = 255;
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), len(6 * s, 14 * s);
    for (int i = 0; i < SceneModel::kStrokes; ++i) {
      const cv::Point a = inside[pick(rng)];
      const double t = angle(rng), l = len(rng);
      const cv::Point b(a.x + static_cast<int>(l * std::cos(t)),
                        a.y + static_cast<int>(l * std::sin(t)));
      cv::line(sc.edges, a, b, 255, 1, cv::LINE_8);
    }
    sc.spurious_pixels = cv::countNonZero(sc.edges & interior);
  }
  return sc;
}

bool truth_is_consistent(const Scene& s, std::string* why) {
  const double area_err = std::abs(s.true_area / s.supersampled_area - 1);
  const double centroid_err = distance(s.true_centroid, s.supersampled_centroid);
  std::string problem;
  if (area_err > SceneModel::kTruthAreaTolerance)
    problem += "area differs from the supersampled count by " + std::to_string(area_err) + "; ";
  if (centroid_err > SceneModel::kTruthCentroidTolerance)
    problem += "centroid differs by " + std::to_string(centroid_err) + " px; ";
  if (s.analytic_area > 0 &&
      std::abs(s.true_area / s.analytic_area - 1) > SceneModel::kTruthAnalyticTolerance)
    problem += "area differs from pi r^2; ";
  if (why) *why = problem;
  return problem.empty();
}

std::vector<Seed> sample_seeds(const Scene& s, int total, std::mt19937& rng) {
  if (s.parts.empty()) return {};
  const int per_part = std::max(1, total / static_cast<int>(s.parts.size()));
  std::vector<Seed> seeds;
  for (const Part& part : s.parts) {
    std::vector<cv::Point> pixels;
    cv::findNonZero(part.mask, pixels);
    if (pixels.empty()) continue;
    std::uniform_int_distribution<std::size_t> pick(0, pixels.size() - 1);
    for (int i = 0; i < per_part; ++i) {
      const cv::Point p = pixels[pick(rng)];
      seeds.push_back({{p.x, p.y}, part.name});
    }
  }
  return seeds;
}

}  // namespace projtrack::synthetic
