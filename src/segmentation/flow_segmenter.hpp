// The flow model's object: its silhouette on every frame, where the last one carried along the
// picture's motion (the prior), the object's colours against its surroundings' and its own motion
// against theirs agree on "object". A stage: the silhouette is its output, the colours and the
// last silhouette its memory.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/frame_pixels.hpp"
#include "motion/dense_flow.hpp"
#include "motion/motion_evidence.hpp"
#include "projtrack/flow_model_params.hpp"
#include "segmentation/colour_mixture.hpp"
#include "segmentation/local_colours.hpp"
#include "segmentation/log_odds_table.hpp"
#include "segmentation/work_images.hpp"

namespace projtrack {

class FlowSegmenter {
 public:
  // A new object: `inside` (CV_8U at the work size, non-zero on the object) on `img` (holding at
  // least images_needed_at_start(inside)); the frame's colours against the object's are learned
  // on `whole` (the whole frame, at any scale), where `whole_inside` (its size) is the object.
  // `outlined`: the silhouette was bounded by an outline of the object (a mask, or the cut within
  // a box), and the colours near each part of it are learned too (LocalColours); from a point,
  // where the first silhouette is a guess at the object's extent, they would hold the background
  // that guess took in as the object's.
  // `refine`: the first silhouette is a start's cut (not the user's own mask), cut again on this
  // frame at the object's scale by the colours just learned (refine_start()).
  void start(const WorkImages& whole, const cv::Mat& whole_inside, const WorkImages& img,
             const cv::Mat& inside, const FlowModelParams& p, bool outlined, bool refine);
  // The part of the frame (work px) the next follow() reads of its images; of start(), with
  // `inside` the first silhouette.
  cv::Rect images_needed(const FlowModelParams& p) const;
  static cv::Rect images_needed_at_start(const cv::Mat& inside, const FlowModelParams& p);
  // What the next follow() costs, work units (about a nanosecond each; work_budget.hpp): the
  // motion measured in the part of the frame it reads (within the frame at the segmenter's
  // scale), at the pyramid level it reads it, and the prior, evidence, cut and learning within
  // that part. Changes nothing: a frame whose budget cannot pay for it is not followed, and the
  // object stays as it was.
  std::uint64_t follow_cost(const FlowModelParams& p) const;
  // The next follow() may cost at most `units`: its motion is read at a coarser level when the
  // usual one would cost more (several objects share a frame's budget), rather than not at all.
  void afford(std::uint64_t units) { affordable_ = units; }
  // What start() on `img` costs, work units.
  static std::uint64_t start_cost(const WorkImages& img);
  // The object on the next frame: its cut, silhouette(). False when nothing of it is left (or
  // the frame's size changed): the silhouette is then empty. The cut is the next frame's
  // starting point and learned from only once accept()ed; refuse() takes it back.
  bool follow(const WorkImages& img, const FlowModelParams& p);
  // The cut on `img` (follow()'s) is the object: its colours are learned, and it is carried on.
  void accept(const WorkImages& img, const FlowModelParams& p);
  // The cut is not the object: the silhouette is the last accepted one carried along this
  // frame's motion (empty, not tracking, when nothing of it is left), and nothing is learned.
  void refuse();
  // Where this frame's cut (between follow() and accept() or refuse()) meets another object's:
  // the mean evidence beside the prior (colours and motion) over the work pixels whose centres
  // lie in `pixels` (-infinity when none does), and the cut without them (false when nothing is
  // left: refuse() then brings back the last accepted silhouette carried along).
  double evidence_over(const FramePixels& pixels) const;
  bool give_up(const FramePixels& pixels);
  // This frame's silhouette, 255 on the object (CV_8U, work size); empty when there is none.
  const cv::Mat& silhouette() const { return mask_; }
  // The silhouette's bounding box (work px): silhouette() is zero outside it.
  const cv::Rect& silhouette_box() const { return box_; }
  bool tracking() const { return !mask_.empty(); }
  int scale() const { return scale_; }
  // How much this frame's own evidence (colours and motion, without the prior) says "object" over
  // the silhouette: its mean log-odds, nats. About none when the frame shows nothing of the
  // object where it was carried (a blank frame, a lens covered).
  double evidence_support() const { return evidence_; }
  // Forgets the silhouette; with `colours` false the colours too.
  void forget(bool colours = true);
  // The work frame is now rx × ry times as large, of `size`, at `scale` (a new frame size, or
  // another scale for an object that grew or shrank): what the segmenter keeps of the object —
  // its silhouettes, its motion, the last frame's picture — is resampled to it, and it follows
  // on.
  void resample(double rx, double ry, cv::Size size, int scale);
  // The frames' colours are read another way (another pixel format): the next follow() learns
  // the object's colours and its surroundings' anew from where the motion carries the silhouette
  // on its frame, before it cuts.
  void relearn_colours() { relearn_ = true; }
  // The last silhouette's area, work px.
  double area() const { return area_; }
  // The object's colours against its surroundings' (kept after forget(false): the object lost
  // is looked for by them).
  const ColourMixture& colours() const { return colours_; }

 private:
  // The prior: the last silhouette carried along the flow, with the remembered one moved by the
  // object's motion; the object's and its surroundings' motions into `split_`.
  void predict(const FlowModelParams& p);
  // The part of the frame whose motion this frame reads (work px): the flow is measured there
  // only. Empty (the whole frame) before there is a silhouette.
  cv::Rect motion_needed(const FlowModelParams& p, int level) const;
  // The pyramid level the next frame's motion is read at: the coarsest at which the object still
  // spans FlowModelParams::flow_span, coarser where the part read is wide for it.
  int level_for(const FlowModelParams& p) const;
  // What a follow() that reads `part` (work px) at pyramid level `level` costs, work units.
  static std::uint64_t cost_at(const cv::Rect& part, int level);
  // The part of a frame of `size` (work px) a frame reads around the silhouette's `box` of `area`
  // work px, for an object that last moved `moved` work px, its motion read at `level`.
  static cv::Rect part_read(const cv::Rect& box, double area, double moved, int level,
                            const FlowModelParams& p, cv::Size size);
  // Where the prior reaches: its support grown by `blur` (work px), within the frame.
  cv::Rect reach_of_prior(int blur);
  // The posterior's log-odds of "object" within reach_, from the prior (blurred `blur` px wide),
  // colours and motion.
  void weigh_evidence(const WorkImages& img, int blur, const FlowModelParams& p);
  // The pixels of reach_ (CV_8U) whose motion counts less (FlowModelParams::new_motion_share);
  // empty when none.
  const cv::Mat& damp_new_pixels(const WorkImages& img, const FlowModelParams& p);
  // The first silhouette cut again on the start's frame by the colours just learned.
  void refine_start(const WorkImages& img, const FlowModelParams& p);
  static constexpr double kRefineSpread = 0.05;  // its prior's blur, a share of √area
  // The prior: the last silhouette where it was (no motion measured), into prior_ and inside_.
  void hold_in_place();
  // Learns the colours anew (relearn_colours()) from the prior's object, inside_, on `img`.
  void relearn_on(const WorkImages& img, const FlowModelParams& p);
  // Follows the colours of the silhouette and of a ring around it.
  void learn_colours(const WorkImages& img, const FlowModelParams& p);
  // The silhouette's square ring (`colour_ring` × √area wide) into `around_`; its box returned.
  cv::Rect colour_ring(const FlowModelParams& p);
  // Keeps the silhouette as the remembered one when it is about as full as the fullest recent.
  void remember(const FlowModelParams& p);
  // The mean of the evidence beside the prior (log_odds_ - prior_odds_) over `mask` (reach_'s).
  double evidence_within(const cv::Mat& mask) const;
  // Keeps the pieces of the thresholded posterior that hold enough of the prior.
  void keep_pieces_on_prior(double keep_share);

  DenseFlow flow_;
  int flow_level_ = DenseFlow::kPresetLevel;  // the flow's pyramid level for this object
  std::uint64_t affordable_ = UINT64_MAX;     // afford()
  ColourMixture colours_;
  LocalColours local_colours_;  // learned only from an outlined first silhouette, then followed
  int scale_ = 1;
  bool outlined_ = false;  // the first silhouette was outlined: the local colours are learned
  bool relearn_ = false;   // relearn_colours()
  double area_ = 0;        // the last silhouette's, work px
  // The images are the work frame's size, zero outside their boxes: a frame's work is within
  // the boxes, not the whole frame.
  cv::Mat last_;         // the last silhouette, CV_32F 0 or 1
  cv::Mat mask_;         // this frame's, CV_8U 0 or 255
  cv::Rect box_;         // mask_'s bounding box
  cv::Rect last_box_;    // last_'s (box_ but between follow() and accept() or refuse())
  cv::Mat memory_;       // the fullest recent silhouette, CV_32F, moved with the object
  cv::Rect memory_box_;  // its bounding box
  cv::Mat prior_;        // this frame's prior, CV_32F
  cv::Rect prior_box_;   // a box that holds all of it
  cv::Mat moved_;        // a buffer: the memory's box moved
  double fullest_ = 0;   // the fullest recent area, fading
  MotionSplit split_;
  LogOddsTable prior_log_odds_;
  cv::Rect reach_;       // this frame's prior's reach: the silhouette lies within it
  cv::Mat prior_odds_;   // the prior's log-odds within reach_
  double evidence_ = 0;  // evidence_support()
  cv::Mat map_, support_, log_odds_, inside_, labels_, ring_count_, around_;  // buffers
  std::vector<float> motion_samples_;                                         // a buffer
  cv::Mat new_pixels_;        // buffer of damp_new_pixels()
  std::vector<double> held_;  // the prior each piece holds
};

}  // namespace projtrack
