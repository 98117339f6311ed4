// The flow model's first silhouette: the user's mask as it is, the object cut out of the user's box
// or around the user's point (segmentation/box_start, point_start), or with no start what the
// search finds (flow_search.cpp).
#include <opencv2/imgproc.hpp>

#include "models/flow/flow_object_model.hpp"
#include "segmentation/arm_trim.hpp"
#include "segmentation/box_start.hpp"
#include "segmentation/point_start.hpp"

namespace projtrack {

FirstSilhouette FlowObjectModel::first_silhouette(FrameEvidence& ev, const StartRequest& request,
                                                  const Track& track, const WorkImages& img) {
  FirstSilhouette start;
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
    // A click on a held object takes in the arm that holds it (segmentation/arm_trim).
    if (start.found && request.from == StartRequest::From::Point)
      trim_arm(img.bgr, {request.point.x / img.scale, request.point.y / img.scale}, ev.budget,
               inside_);
    return start;
  }
  if (request.from == StartRequest::From::Lost) return find_again(ev, track, img);
  return search(ev, track, img);
}

}  // namespace projtrack
