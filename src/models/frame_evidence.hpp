// What one frame gives every object model, made once a frame outside the models (so that several
// objects could share it): the frame, its edges on demand, the frame at a working scale on
// demand, the frame's work budget, and the settings and estimator it is tracked with.
#pragma once

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
  FrameEvidence(const ColorView& frame, EdgeSource& edges, WorkBudget& budget, Estimator& est,
                Method method, const Params& params, const TrackerParams& tp, Trace* trace,
                WorkImages& images)
      : frame(frame),
        edges(edges),
        budget(budget),
        estimator(est),
        method(method),
        params(params),
        tp(tp),
        trace(trace),
        images_(images) {}

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
  // The whole frame at `scale` (segmentation/work_images), built on the frame's first call for
  // that scale and shared by every later one.
  const WorkImages& images(int scale);

 private:
  WorkImages& images_;
  int images_scale_ = 0;  // the scale images_ holds this frame (0: none yet)
};

}  // namespace projtrack
