// The flow model's first silhouette: the user's mask as it is, the object in the user's box, or
// for a point or nothing the appearance model's start checked against the objects around the
// point (segmentation/box_start, point_start).
#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "models/flow/flow_object_model.hpp"
#include "segmentation/box_start.hpp"
#include "segmentation/point_start.hpp"

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

}  // namespace projtrack
