// The flow model's first silhouette: the user's mask as it is, the object cut out of the user's box
// or around the user's point (segmentation/box_start, point_start), or with no start the
// appearance model's.
#include <opencv2/imgproc.hpp>

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
  if (request.from == StartRequest::From::Box || request.from == StartRequest::From::Point) {
    const StartOutcome cut =
        request.from == StartRequest::From::Box
            ? object_in_box(ev.frame, request.box, ev.tp.flow.box_pixels, img.size(), cut_work_,
                            ev.budget, inside_)
            : object_at_point(ev.frame, request.point, img.size(), cut_work_, ev.budget, inside_);
    start.found = cut.kind == StartOutcome::Kind::Cut;
    start.why = cut.why;
    return start;
  }
  // Nothing: the appearance model's start finds the object's first silhouette.
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
  return start;
}

}  // namespace projtrack
