// libFuzzer target over the library: random edge maps and gray frames of random sizes and
// strides, random inner points (inside, outside, extreme), every method, every parameter in and
// out of range, and a few tracker frames. It checks the promises of the API, not just "no crash":
// a result with features is finite, inside the frame, and its inner point is a free pixel.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "fuzz_input.hpp"
#include "projtrack/edge_detection.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/multi_tracker.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"

namespace {

using namespace projtrack;

using fuzz::check;
using fuzz::Input;

// Any row of the table of methods.
Method any_method(Input& in) { return kAllMethods[in.in(0, kMethodCount - 1)]; }

void check_features(const Features& f, const ImageView& edges, Method m) {
  if (!f.valid()) return;
  check(std::isfinite(f.centroid.x) && std::isfinite(f.centroid.y) && std::isfinite(f.area),
        "finite features");
  check(f.area >= 0, "area >= 0");
  const double w = edges.width, h = edges.height;
  // Rays end half a pixel past the last free pixel, so polygons may reach half a pixel beyond.
  check(f.area <= (w + 1) * (h + 1) + 1e-6, "area within the frame");
  check(f.centroid.x >= -0.5 && f.centroid.x <= w - 0.5 && f.centroid.y >= -0.5 &&
            f.centroid.y <= h - 0.5,
        "centroid inside the frame");
  check(!f.bbox.empty() && clip_to_frame(f.bbox, edges.width, edges.height) == f.bbox,
        "bounding box inside the frame");
  check(edges.contains(f.inner_point.x, f.inner_point.y), "inner point inside the frame");
  check(edges.at(f.inner_point.x, f.inner_point.y) == 0, "inner point on a free pixel");
  check(edges.at(f.seed.x, f.seed.y) == 0, "seed on a free pixel");
  if (!is_ray_method(m)) {
    check(f.bbox.x <= f.centroid.x && f.centroid.x <= f.bbox.right() - 1 &&
              f.bbox.y <= f.centroid.y && f.centroid.y <= f.bbox.bottom() - 1,
          "fill centroid inside its box");
  }
}

// A model with a silhouette measures the estimate on its outline, not on the edges given: the
// features are finite and inside the frame, and the inner point is on the silhouette.
void check_on_silhouette(const Tracker& tracker, const Features& f, int w, int h) {
  check(std::isfinite(f.centroid.x) && std::isfinite(f.centroid.y) && std::isfinite(f.area) &&
            f.area >= 0,
        "finite features");
  check(!f.bbox.empty() && clip_to_frame(f.bbox, w, h) == f.bbox, "bounding box inside the frame");
  check(f.inner_point.x >= 0 && f.inner_point.x < w && f.inner_point.y >= 0 && f.inner_point.y < h,
        "inner point inside the frame");
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(w) * h);
  if (tracker.silhouette(mask.data(), w, h, w))
    check(mask[static_cast<std::size_t>(f.inner_point.y) * w + f.inner_point.x] != 0,
          "inner point on the silhouette");
}

// Several objects on the same frames: starts anywhere (refused with a reason, or an id never seen
// before), removals of any id, and frames whose results are one per object, in ids() order, with
// finite features inside the frame, never more work than the frame's bound.
void fuzz_several_objects(Input& in, const ImageView& frame, const EdgeParams& ep, const Params& p,
                          const TrackerParams& tp) {
  const int w = frame.width, h = frame.height;
  MultiTracker objects(static_cast<std::size_t>(in.in(0, 4)));
  int last_id = 0;
  for (int step = 0; step < 6; ++step) {
    const int what = in.in(0, 3);
    Added a;
    if (what == 0) a = objects.add_point({in.in(-5, 60), in.in(-5, 60)}, w, h);
    if (what == 1)
      a = objects.add_box({in.in(-5, 60), in.in(-5, 60), in.in(-2, 30), in.in(-2, 30)}, w, h);
    if (what == 2) objects.remove(in.in(-1, 6));
    if (what <= 1) check(a ? a.id > last_id && a.why.empty() : !a.why.empty(), "a new id or why");
    if (a) last_id = a.id;
    const std::vector<TrackResult> rs =
        objects.track(frame, ep, step / 30.0, any_method(in), p, tp);
    check(rs.size() == objects.size(), "one result per object");
    std::uint64_t work = 0;
    for (std::size_t i = 0; i < rs.size(); ++i) {
      check(rs[i].id == objects.ids()[i], "results in ids() order");
      work += rs[i].work;
      if (!has_features(rs[i].status)) continue;
      const Features& f = rs[i].features;
      check(std::isfinite(f.centroid.x) && std::isfinite(f.centroid.y) && std::isfinite(f.area),
            "finite features of each object");
      check(!f.bbox.empty() && clip_to_frame(f.bbox, w, h) == f.bbox, "each object inside");
    }
    if (tp.max_work > 0)
      check(work <= frame_work_limit(w, h, tp) + rs.size() * overshoot_bound(w, h),
            "several objects within one frame's budget");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int w = in.in(0, 48), h = in.in(0, 48), pad = in.in(0, 9);
  const int stride_mode = in.in(0, 15);  // mostly stride >= width; sometimes invalid
  const std::ptrdiff_t stride = stride_mode == 0 ? std::max(0, w - 1) : w + pad;
  Params p;
  p.rays = in.in(0, 40);  // bounded so one input stays well under a second: 40^3 rays a cast
  p.recursion = in.in(0, 5);
  if (p.recursion > 3 && p.rays > 6) p.recursion = 3;
  p.block_size = in.in(0, 70);
  p.grid_size = in.in(0, 70);
  p.max_iterations = in.in(0, 8);
  p.convergence = in.in(0, 5) == 0 ? std::numeric_limits<double>::quiet_NaN() : in.in(0, 80) / 8.0;
  p.seed_radius = in.in(0, 70);
  const int density = in.in(0, 255);  // share of edge pixels in the random part

  // The frame: explicit bytes while the input lasts, then a pattern; padding is garbage.
  std::vector<std::uint8_t> px(
      static_cast<std::size_t>(std::max<std::ptrdiff_t>(stride, 1)) * std::max(h, 1) + 16, 0xA5);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t b = in.left() ? in.byte() : static_cast<std::uint8_t>(x * 7 + y * 13);
      px[y * stride + x] = b < density ? 255 : 0;
    }
  const ImageView edges(px.data(), w, h, stride);
  // A work budget for the estimates, from bytes already read (so the corpus keeps its meaning):
  // none, or a small one that cuts the heavier of them short.
  const std::uint64_t limit = p.block_size % 4 == 0
                                  ? WorkBudget::kUnlimited
                                  : static_cast<std::uint64_t>(density) * 64 + p.grid_size;

  for (Method m : kAllMethods) {
    auto est = make_estimator(m);
    const Point2i points[] = {{in.in(-60, 110), in.in(-60, 110)},
                              {std::numeric_limits<int>::max(), in.in(0, 48)},
                              {std::numeric_limits<int>::min(), std::numeric_limits<int>::min()},
                              {w / 2, h / 2}};
    for (Point2i q : points) {
      Trace trace;
      WorkBudget budget(limit);
      EstimateOptions options;
      options.budget = &budget;
      const Features f = est->estimate(edges, q, p, options, in.in(0, 1) ? &trace : nullptr);
      check_features(f, edges, m);
      if (f.status == EstimateStatus::OverBudget) check(!f.valid(), "over budget: no features");
      if (limit != WorkBudget::kUnlimited)
        check(budget.spent() <= limit + overshoot_bound(w, h), "work within the budget");
    }
  }

  // The edge detectors over the same bytes read as gray, then a few tracker frames on them.
  EdgeParams ep;
  ep.detector = static_cast<EdgeDetector>(in.in(0, 2));
  ep.low = in.in(-10, 300);
  ep.high = in.in(-10, 600);
  ep.blur = in.in(-2, 20);
  ep.input_black_level = in.in(0, 40);
  EdgeMap map;
  const ImageView detected = map.detect(edges, ep);
  check(detected.empty() || (detected.width == w && detected.height == h), "edge map size");
  Tracker tracker;
  TrackerParams tp;
  tp.max_work = p.grid_size % 3 == 0 ? 0 : p.grid_size / 10.0;  // from bytes already read
  tp.acquisition = static_cast<Acquisition>(in.in(0, 2));
  tp.strategy = static_cast<AutoAcquisition>(in.in(0, 1));
  if (in.in(0, 1)) tracker.seed({in.in(-5, 60), in.in(-5, 60)});
  // The element's path: the tracker computes the edges itself, on regions around the object.
  Tracker regional;
  if (in.in(0, 1)) regional.seed({in.in(-5, 60), in.in(-5, 60)});
  for (int frame = 0; frame < 3; ++frame) {
    const TrackResult r = regional.track(edges, ep, frame / 30.0, any_method(in), p, tp);
    check(r.work <= r.work_limit || r.work - r.work_limit <= overshoot_bound(w, h),
          "a frame's work within its budget");
    if (has_features(r.status)) {
      check(
          std::isfinite(r.features.area) && clip_to_frame(r.features.bbox, w, h) == r.features.bbox,
          "regional estimate inside the frame");
    }
  }
  for (int frame = 0; frame < 3; ++frame) {
    const TrackResult r = tracker.track(edges, detected.empty() ? edges : detected, frame / 30.0,
                                        any_method(in), p, tp);
    if (has_features(r.status)) {
      if (tp.model == ObjectModelKind::Edges)
        check_features(r.features, detected.empty() ? edges : detected, static_cast<Method>(0));
      else
        check_on_silhouette(tracker, r.features, w, h);
    }
    if (r.has_pose)
      check(std::isfinite(r.pose.x) && std::isfinite(r.pose.y) && std::isfinite(r.pose.depth),
            "finite pose");
  }
  fuzz_several_objects(in, edges, ep, p, tp);
  return 0;
}
