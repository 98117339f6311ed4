// The flow model's step: the object's silhouette carried along the picture's motion and cut from
// its surroundings (segmentation/flow_segmenter), and the estimator on that silhouette.
#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "core/plausibility.hpp"
#include "core/work_frame.hpp"
#include "segmentation/box_start.hpp"
#include "segmentation/point_start.hpp"
#include "tracker/tracker_impl.hpp"

namespace projtrack {

namespace {

// `m` (work coordinates at scale `from`) at the flow model's scale, 255 on the object: each work
// pixel takes the value under its centre.
void mask_at_scale(const Mask& m, int from, const WorkImages& img, cv::Mat& out) {
  out = cv::Mat::zeros(img.size(), CV_8U);
  for (int y = 0; y < out.rows; ++y) {
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    const int fy = (y * img.scale + img.scale / 2) / from;
    for (int x = 0; x < out.cols; ++x)
      if (m.at({(x * img.scale + img.scale / 2) / from, fy})) o[x] = 255;
  }
}

}  // namespace

TrackResult Tracker::Impl::track_flow(const ColorView& frame, EdgeSource& edges,
                                      const FrameInput& in) {
  const double pixels = static_cast<double>(frame.luma.width) * frame.luma.height;
  build_work_images(frame, work_scale(pixels, in.tp.flow.work_pixels), work.images);
  return state.flow.tracking() ? follow_flow(frame, in) : start_flow(frame, edges, in);
}

AppearanceStart Tracker::Impl::first_flow_silhouette(const ColorView& frame, EdgeSource& edges,
                                                     const FrameInput& in) {
  const TrackerState::Track& t = state.track();
  const WorkImages& img = work.images;
  AppearanceStart start;
  if (!t.seed_mask.empty()) {
    cv::resize(t.seed_mask, work.inside, img.size(), 0, 0, cv::INTER_AREA);
    cv::compare(work.inside, 127, work.inside, cv::CMP_GT);
    start.found = cv::countNonZero(work.inside) > 0;
    if (!start.found) start.why = "the given mask covers no pixel at the working scale";
    return start;
  }
  if (t.seed_box) {
    WorkImages full;  // the box is cut at its own resolution, not the working frame's
    build_work_images(frame, 1, full);
    object_in_box(full.bgr, *t.seed_box, in.tp.flow.box_pixels, img.size(), work.inside);
    start.found = true;
    return start;
  }
  // A point, or none: the appearance model finds the object's first silhouette; its colours stay
  // known to find the object again after a loss.
  const std::optional<Point2i> point = t.inner;
  start = start_appearance_track(state, as_appearance_reads(frame, in.tp), edges, in.tp, work.first,
                                 work.silhouette);
  if (start.found) {
    mask_at_scale(work.silhouette, state.object.scale(), img, work.inside);
    state.object.forget_position();
  }
  if (point) choose_at_point(*point, start);
  return start;
}

void Tracker::Impl::choose_at_point(Point2i point, AppearanceStart& start) {
  // The appearance model's region is one colour region (a patch of a cow, nothing of a camel of
  // the sand's colour): GrabCut around the point at a tenth to two fifths of the frame's height
  // joins it as candidates, and the one the others agree with most is taken.
  const WorkImages& img = work.images;
  const cv::Point p(std::clamp(point.x / img.scale, 0, img.bgr.cols - 1),
                    std::clamp(point.y / img.scale, 0, img.bgr.rows - 1));
  const int h = img.bgr.rows;
  std::vector<cv::Mat> candidates =
      objects_at_point(img, p, {h / 10, h / 5, 3 * h / 10, 2 * h / 5});
  if (start.found) candidates.insert(candidates.begin(), work.inside);
  const int chosen = most_agreed(candidates);
  if (chosen < 0 || (start.found && chosen == 0)) return;
  cv::swap(work.inside, candidates[chosen]);
  start.found = true;
  start.resumed = false;
  start.why.clear();
}

Features Tracker::Impl::estimate_flow_silhouette(const ColorView& frame, const FrameInput& in) {
  const cv::Mat& m = state.flow.silhouette();
  const cv::Rect& b = state.flow.silhouette_box();
  work.silhouette.reset({b.x, b.y, b.width, b.height});
  for (int y = 0; y < b.height; ++y) {
    const std::uint8_t* from = m.ptr<std::uint8_t>(b.y + y) + b.x;
    std::uint8_t* to = work.silhouette.row(y);
    for (int x = 0; x < b.width; ++x) to[x] = from[x] ? 1 : 0;
  }
  return estimate_silhouette(frame, state.flow.scale(), in);
}

TrackResult Tracker::Impl::start_flow(const ColorView& frame, EdgeSource& edges,
                                      const FrameInput& in) {
  if (waits_for_user(state, in.tp))
    return not_started(kNoInnerPoint, false, in.tp, TrackStatus::NoInnerPoint);
  TrackResult r;
  const int w = frame.luma.width, h = frame.luma.height;
  const bool seeded = state.track().inner.has_value();
  // A mask or a box bounds the first silhouette; a point does not.
  const bool outlined = !state.track().seed_mask.empty() || state.track().seed_box.has_value();
  AppearanceStart start = first_flow_silhouette(frame, edges, in);
  if (start.found) {
    state.flow.start(work.images, work.inside, in.tp.flow, outlined);
    const Features f = estimate_flow_silhouette(frame, in);
    if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
      state.flow.forget(false);
      stopped(f, in.tp, r);
      return r;
    }
    start.why = why_implausible(f, w, h, in.tp, seeded ? Origin::User : Origin::Found);
    if (start.why.empty()) {
      accept(f, w, h, in, start.resumed, r);
      return r;
    }
    state.flow.forget(false);
  } else if (work_stopped()) {
    stopped(Features{}, in.tp, r);
    return r;
  }
  return not_started(std::move(start.why), seeded, in.tp);
}

TrackResult Tracker::Impl::follow_flow(const ColorView& frame, const FrameInput& in) {
  TrackResult r;
  if (!state.flow.follow(work.images, in.tp.flow)) {
    refuse("nothing of the object is left where the picture's motion carried it", in.tp, r);
    return r;
  }
  const Features f = estimate_flow_silhouette(frame, in);
  if (f.status == EstimateStatus::OverBudget || f.status == EstimateStatus::Interrupted) {
    stopped(f, in.tp, r);
    return r;
  }
  const Origin origin = state.track().seeded ? Origin::User : Origin::Found;
  if (std::string why = why_implausible(f, frame.luma.width, frame.luma.height, in.tp, origin);
      !why.empty()) {
    refuse(std::move(why), in.tp, r);
    return r;
  }
  accept(f, frame.luma.width, frame.luma.height, in, false, r);
  return r;
}

}  // namespace projtrack
