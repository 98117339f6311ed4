#include "models/flow/flow_object_model.hpp"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "core/work_frame.hpp"
#include "segmentation/box_start.hpp"
#include "segmentation/point_start.hpp"

namespace projtrack {

template <>
std::unique_ptr<ObjectModel> make_object_model<ObjectModelKind::Flow>() {
  return std::make_unique<FlowObjectModel>();
}

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

const WorkImages& work_images(FrameEvidence& ev) {
  const double pixels = static_cast<double>(ev.width()) * ev.height();
  return ev.images(work_scale(pixels, ev.tp.flow.work_pixels));
}

}  // namespace

AppearanceStart FlowObjectModel::first_silhouette(FrameEvidence& ev, const StartRequest& request,
                                                  const Track& track, const WorkImages& img) {
  AppearanceStart start;
  if (request.from == StartRequest::From::Mask) {
    cv::resize(*request.mask, inside_, img.size(), 0, 0, cv::INTER_AREA);
    cv::compare(inside_, 127, inside_, cv::CMP_GT);
    start.found = cv::countNonZero(inside_) > 0;
    if (!start.found) start.why = "the given mask covers no pixel at the working scale";
    return start;
  }
  if (request.from == StartRequest::From::Box) {
    WorkImages full;  // the box is cut at its own resolution, not the working frame's
    build_work_images(ev.frame, 1, full);
    object_in_box(full.bgr, request.box, ev.tp.flow.box_pixels, img.size(), inside_);
    start.found = true;
    return start;
  }
  // A point, or none: the appearance model's start finds the object's first silhouette.
  if (!finder_.object.knows_colours())
    finder_.exposure =
        exposure_for(luma_range(ev.frame.luma), ev.tp.dim_white, ev.tp.full_contrast);
  ColorView frame = ev.frame;
  frame.exposure = finder_.exposure;
  start = start_appearance_track(finder_, frame, ev.edges, request, track, ev.tp, first_, found_);
  if (start.found) {
    mask_at_scale(found_, finder_.object.scale(), img, inside_);
    finder_.object.forget_position();
  }
  if (request.from == StartRequest::From::Point) choose_at_point(img, request.point, start);
  return start;
}

void FlowObjectModel::choose_at_point(const WorkImages& img, Point2i point,
                                      AppearanceStart& start) {
  // The appearance model's region is one colour region (a patch of a cow, nothing of a camel of
  // the sand's colour): GrabCut around the point at a tenth to two fifths of the frame's height
  // joins it as candidates, and the one the others agree with most is taken.
  const cv::Point p(std::clamp(point.x / img.scale, 0, img.bgr.cols - 1),
                    std::clamp(point.y / img.scale, 0, img.bgr.rows - 1));
  const int h = img.bgr.rows;
  std::vector<cv::Mat> candidates =
      objects_at_point(img, p, {h / 10, h / 5, 3 * h / 10, 2 * h / 5});
  if (start.found) candidates.insert(candidates.begin(), inside_);
  const int chosen = most_agreed(candidates);
  if (chosen < 0 || (start.found && chosen == 0)) return;
  cv::swap(inside_, candidates[chosen]);
  start.found = true;
  start.resumed = false;
  start.why.clear();
}

Observation FlowObjectModel::observed(bool resumed) {
  const cv::Mat& m = segmenter_.silhouette();
  const cv::Rect& b = segmenter_.silhouette_box();
  silhouette_.reset({b.x, b.y, b.width, b.height});
  for (int y = 0; y < b.height; ++y) {
    const std::uint8_t* from = m.ptr<std::uint8_t>(b.y + y) + b.x;
    std::uint8_t* to = silhouette_.row(y);
    for (int x = 0; x < b.width; ++x) to[x] = from[x] ? 1 : 0;
  }
  return Observation::of_silhouette(silhouette_, segmenter_.scale(), resumed);
}

Observation FlowObjectModel::start(FrameEvidence& ev, const StartRequest& request,
                                   const Track& track) {
  const WorkImages& img = work_images(ev);
  // A mask or a box bounds the first silhouette; a point does not.
  const bool outlined =
      request.from == StartRequest::From::Mask || request.from == StartRequest::From::Box;
  const AppearanceStart start = first_silhouette(ev, request, track, img);
  if (!start.found) {
    if (ev.budget.ran_out() || ev.budget.interrupted()) return Observation::stopped();
    return Observation::missing(start.why);
  }
  segmenter_.start(img, inside_, ev.tp.flow, outlined);
  starting_ = true;
  return observed(start.resumed);
}

Observation FlowObjectModel::follow(FrameEvidence& ev, const Track&) {
  starting_ = false;
  if (!segmenter_.follow(work_images(ev), ev.tp.flow))
    return Observation::missing(
        "nothing of the object is left where the picture's motion carried it");
  return observed(false);
}

Veto FlowObjectModel::veto(FrameEvidence&, const Features&, const Track&) {
  // The silhouette carried where the motion says, but this frame's colours and motion do not say
  // "object" there as they did: a blank frame, a covered lens, a cut to another shot. Judged
  // against the track's own usual evidence (objects differ by tens of nats in how far their
  // colours stand apart).
  if (starting_ || !(usual_support_ > 0)) return {};
  const double support = segmenter_.evidence_support();
  if (support >= kLeastSupport * usual_support_) return {};
  char why[160];
  std::snprintf(why, sizeof why,
                "this frame shows little of the object where it was carried: its colours and "
                "motion say %.2g nats against the track's usual %.2g",
                support, usual_support_);
  return {why, false};
}

void FlowObjectModel::settle(Verdict verdict) {
  // A start not taken leaves nothing to follow.
  if (starting_ && verdict != Verdict::Accepted) segmenter_.forget(false);
  if (!starting_ && verdict == Verdict::Accepted) {
    const double support = segmenter_.evidence_support();
    usual_support_ =
        usual_support_ > 0 ? (1 - kSupportRate) * usual_support_ + kSupportRate * support : support;
  }
  if (starting_) usual_support_ = 0;
  starting_ = false;
}

bool FlowObjectModel::rescale(double, double) { return relearn(); }

bool FlowObjectModel::relearn() {
  segmenter_.forget();
  finder_.object.forget();
  finder_.forget_motion();
  return false;
}

void FlowObjectModel::forget(Forget) {
  segmenter_.forget();
  finder_.object.forget();
  finder_.forget_motion();
  finder_.searched = 0;
}

SilhouetteMask FlowObjectModel::silhouette(int frame_width, int frame_height) const {
  const cv::Mat& m = segmenter_.silhouette();
  const cv::Rect& b = segmenter_.silhouette_box();
  if (m.empty() || b.empty()) return {};
  return {ImageView(m.ptr(b.y) + b.x, b.width, b.height, static_cast<std::ptrdiff_t>(m.step)),
          Rect{b.x, b.y, b.width, b.height}, segmenter_.scale(), frame_width, frame_height};
}

}  // namespace projtrack
