// What one frame gives every object model, made once a frame outside the models (so that several
// objects could share it): the frame, its edges on demand, the frame at a working scale on
// demand, the frame's work budget, and the settings and estimator it is tracked with.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "edges/edge_source.hpp"
#include "projtrack/color_view.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/method.hpp"
#include "projtrack/params.hpp"
#include "projtrack/trace.hpp"
#include "projtrack/tracker_params.hpp"
#include "projtrack/work_budget.hpp"
#include "segmentation/work_images.hpp"

namespace projtrack {

class FrameEvidence {
 public:
  // The work images are built into `images`' slots (kept from frame to frame: their buffers are
  // reused, what they hold is this frame's only once built on it), one a scale asked for.
  using ImageSlots = std::deque<WorkImages>;  // a slot added leaves the others in place
  FrameEvidence(const ColorView& frame, EdgeSource& edges, WorkBudget& budget, Estimator& est,
                Method method, const Params& params, const TrackerParams& tp, Trace* trace,
                ImageSlots& images)
      : frame(frame),
        edges(edges),
        budget(budget),
        estimator(est),
        method(method),
        params(params),
        tp(tp),
        trace(trace),
        slots_(images),
        scales_(images.size(), 0) {}

  const ColorView& frame;  // as given (video range; a gray frame has no chroma)
  EdgeSource& edges;       // the frame's edges, computed within the region asked for
  WorkBudget& budget;      // this frame's: every stage spends from it
  Estimator& estimator;    // the estimator of `method`
  const Method method;
  const Params& params;
  const TrackerParams& tp;
  Trace* const trace;

  int width() const { return frame.luma.width; }
  int height() const { return frame.luma.height; }
  // The frame at `scale` (segmentation/work_images) within `region` (work px; empty: the whole
  // frame), built when this frame's images at that scale do not hold it yet, and shared by every
  // later call; null when the budget cannot pay for reading that part of the frame
  // (images_cost) or the stop flag is set. Every scale and part asked for on a frame is held
  // until the frame ends (a start reads the whole frame at one scale, each object its own part at
  // its own; parts far apart at one scale in slots of their own): a pointer returned stays valid
  // and unchanged but for the part other calls add to it.
  const WorkImages* images(int scale, const cv::Rect& region = cv::Rect());
  // What building the work images of `part` (frame px) at `scale` costs, work units: every frame
  // pixel read (luma and chroma, a block mean each), and each work pixel converted.
  static std::uint64_t images_cost(const cv::Rect& part, int scale);

 private:
  // A slot that holds no scale on this frame (added when every slot does).
  int free_slot();

  ImageSlots& slots_;
  std::vector<int> scales_;  // the scale each slot holds this frame at (0: none yet)
};

}  // namespace projtrack
