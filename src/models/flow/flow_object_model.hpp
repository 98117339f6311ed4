// The flow model (ObjectModelKind::Flow): the whole object as it moves. Its last silhouette is
// carried along the picture's dense motion and cut from its surroundings where that prior, the
// colours of both and the motion of both agree (segmentation/flow_segmenter). It starts from the
// user's mask as it is, from the object cut out of the user's box (segmentation/box_start) or
// around the user's point (segmentation/point_start), and with no start from the object lost
// before, found again by its colours, or the object that moves apart from the picture's own
// motion (flow_search.cpp).
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "acquisition/moving_object.hpp"
#include "models/object_model.hpp"
#include "segmentation/flow_segmenter.hpp"
#include "segmentation/start_cut.hpp"

namespace projtrack {

// How a start found the object's first silhouette.
struct FirstSilhouette {
  bool found = false;
  bool resumed = false;  // the object lost before, found again by its colours
  std::string why;       // when not found
};

class FlowObjectModel final : public ObjectModel {
 public:
  bool tracking() const override { return segmenter_.tracking(); }
  Observation start(FrameEvidence& ev, const StartRequest& request, const Track& track) override;
  Observation follow(FrameEvidence& ev, const Track& track) override;
  Veto veto(FrameEvidence& ev, const Features& f, const Track& track) override;
  void settle(Verdict verdict) override;
  bool rescale(double sx, double sy, int width, int height) override;
  bool relearn() override;
  void forget(Forget what) override;
  SilhouetteMask silhouette(int frame_width, int frame_height) const override;
  double explains(const FramePixels& pixels) const override;
  Observation give_up(const FramePixels& pixels, const Observation& o) override;

 private:
  // The first silhouette, into inside_ (the work images' size): the user's mask, the object cut
  // out of the user's box or around the user's point, or with no start what search() finds.
  FirstSilhouette first_silhouette(FrameEvidence& ev, const StartRequest& request,
                                   const Track& track, const WorkImages& img);
  // The object started at its own scale from inside_ (the start's whole-frame work images'
  // size), or from the user's `mask` when given; `outlined`: a mask or a box bounded it.
  Observation begin(FrameEvidence& ev, const WorkImages& whole, const cv::Mat* mask, bool outlined,
                    bool resumed);
  // After a new size: the object found again by its colours near where it was and begun there,
  // into `o` (false, following on from the resampled silhouette, when it is not found).
  bool found_again(FrameEvidence& ev, const Track& track, Observation& o);
  // The object followed at the scale its size asks for (FlowModelParams::object_pixels), or a
  // coarser one at which its follow costs at most `affordable` work units.
  void follow_scale(const FrameEvidence& ev, std::uint64_t affordable);
  // The object followed at `scale` from now on (its silhouette resampled).
  void follow_at(const FrameEvidence& ev, int scale);
  // A start nobody pointed at (flow_search.cpp), into inside_ (`whole`'s size): by
  // TrackerParams::acquisition, the object at the frame's centre, or the object lost before where
  // its colours are near where it was lost and something moves, else the object that moves apart
  // from the picture's own motion (acquisition/moving_object).
  FirstSilhouette search(FrameEvidence& ev, const Track& track, const WorkImages& whole);
  // The track's object, lost mid-track, found again by its colours near its last estimate
  // (flow_search.cpp); not found: the track is refused until it is, or dropped.
  FirstSilhouette find_again(FrameEvidence& ev, const Track& track, const WorkImages& whole);
  // The object by its colours: a piece of them within kReach × √area of `near` (frame px), of
  // about `area` (frame px, within leak_factor² of it), where `moved` (when not empty) says it
  // moved since the last frame searched (a static patch of its colours is not it).
  bool find_by_colours(FrameEvidence& ev, Point2d near, double area, const WorkImages& whole,
                       const cv::Mat& moved);
  // The moving region found (inside_) replaced by the object cut out of its box, when the cut
  // agrees with it.
  void refine_in_box(FrameEvidence& ev, const WorkImages& whole);
  // Where `gray` (the whole work frame) changed since the last frame searched, beyond its noise,
  // into moved_; false on the first frame searched.
  bool changed_since_last(const cv::Mat& gray);
  // The segmenter's silhouette as the estimator reads it (a Mask of its box).
  Observation observed(bool resumed);

  FlowSegmenter segmenter_;
  // This frame's images and settings while its follow() awaits the verdict (settle()).
  const WorkImages* followed_ = nullptr;
  const FlowModelParams* followed_params_ = nullptr;
  CutWorkspace cut_work_;      // the box's and the point's cuts (kept: their buffers are reused)
  MovingObjectFinder moving_;  // the moving object, when nobody points at one
  int searched_ = 0;           // frames searched since the object was lost (or forgotten)
  double largest_area_ = 0;    // the largest area accepted on its track, frame px
  // Buffers of the search: the last frame searched, what changed since, the colours' log-odds,
  // the pieces.
  cv::Mat last_searched_, moved_, colour_odds_, pieces_, piece_stats_, piece_centres_, refined_,
      known_;
  Mask silhouette_;        // this frame's silhouette, as the estimator reads it
  cv::Mat inside_;         // the first silhouette, at the start's working scale
  cv::Mat object_inside_;  // the same at the object's scale
  int scale_ = 1;          // the object's scale (FlowModelParams::object_pixels)
  double object_pixels_ = FlowModelParams{}.object_pixels;  // the last frame's
  bool starting_ = false;                                   // this frame's observation is a start
  bool refind_ = false;  // the frames changed size: found_again() on the next one
  // The evidence (FlowSegmenter::evidence_support) of the track's accepted frames, followed at
  // kSupportRate; a frame with less than kLeastSupport of it is refused (veto()). On davis-dev the
  // least frame of a track held 0.43 of its median or more (drift-chicane's car in smoke), a
  // blank frame 0.13 (the first, read with the motion from the last picture) and none after.
  double usual_support_ = 0;
  static constexpr double kSupportRate = 0.1;
  static constexpr double kLeastSupport = 0.25;
};

}  // namespace projtrack
