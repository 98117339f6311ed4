// The flow model (ObjectModelKind::Flow): the whole object as it moves. Its last silhouette is
// carried along the picture's dense motion and cut from its surroundings where that prior, the
// colours of both and the motion of both agree (segmentation/flow_segmenter). It starts from the
// user's mask as it is, from the object cut out of the user's box (segmentation/box_start) or
// around the user's point (segmentation/point_start), and with no start from the appearance
// model's first silhouette.
#pragma once

#include <opencv2/core.hpp>

#include "models/appearance/appearance_memory.hpp"
#include "models/object_model.hpp"
#include "segmentation/flow_segmenter.hpp"
#include "segmentation/start_cut.hpp"

namespace projtrack {

class FlowObjectModel final : public ObjectModel {
 public:
  bool tracking() const override { return segmenter_.tracking(); }
  Observation start(FrameEvidence& ev, const StartRequest& request, const Track& track) override;
  Observation follow(FrameEvidence& ev, const Track& track) override;
  Veto veto(FrameEvidence& ev, const Features& f, const Track& track) override;
  void settle(Verdict verdict) override;
  bool rescale(double sx, double sy) override;
  bool relearn() override;
  void forget(Forget what) override;
  SilhouetteMask silhouette(int frame_width, int frame_height) const override;

 private:
  // The first silhouette, into inside_ (the work images' size): the user's mask, the object cut
  // out of the user's box or around the user's point, or with no start the appearance model's.
  AppearanceStart first_silhouette(FrameEvidence& ev, const StartRequest& request,
                                   const Track& track, const WorkImages& img);
  // The segmenter's silhouette as the estimator reads it (a Mask of its box).
  Observation observed(bool resumed);

  FlowSegmenter segmenter_;
  CutWorkspace cut_work_;    // the box's and the point's cuts (kept: their buffers are reused)
  AppearanceMemory finder_;  // how a start with no seed finds the object's first silhouette
  Mask first_, found_;       // the finder's buffers
  Mask silhouette_;          // this frame's silhouette, as the estimator reads it
  cv::Mat inside_;           // the first silhouette, at the start's working scale
  cv::Mat object_inside_;    // the same at the object's scale
  int scale_ = 1;            // the object's scale (FlowModelParams::object_pixels)
  bool starting_ = false;    // this frame's observation is a start
  // The evidence (FlowSegmenter::evidence_support) of the track's accepted frames, followed at
  // kSupportRate; a frame with less than kLeastSupport of it is refused (veto()). On davis-dev the
  // least frame of a track held 0.43 of its median or more (drift-chicane's car in smoke), a
  // blank frame 0.13 (the first, read with the motion from the last picture) and none after.
  double usual_support_ = 0;
  static constexpr double kSupportRate = 0.1;
  static constexpr double kLeastSupport = 0.25;
};

}  // namespace projtrack
