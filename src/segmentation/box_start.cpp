#include "segmentation/box_start.hpp"

#include "segmentation/cut_pieces.hpp"
#include "segmentation/cut_problem.hpp"
#include "segmentation/start_work.hpp"

namespace projtrack {

namespace {

constexpr double kContext = 0.5;  // the surroundings: the box grown by half its sides
// The box holds the object and some of its surroundings: its first colours are the box's less the
// ring's (davis-dev's first silhouettes 0.583 -> 0.605, tracked J from the box 50.3 -> 57.6: the
// cows' shadowed ground, the camel's fence, the dog's hedge left out; the real clips' 0.805 ->
// 0.803).
constexpr CutSettings kBoxCut{2, true, 2, true};
constexpr int kGrowths = 2;

CutHypothesis box_hypothesis(const cv::Rect& box, double box_pixels) {
  CutHypothesis h;
  h.box = box;
  h.pixels = box_pixels;
  h.context = kContext;
  h.centre = {box.x + box.width / 2.0, box.y + box.height / 2.0};
  h.radii = {box.width / 2.0, box.height / 2.0};
  return h;
}

// The object cut out of `box` (within the frame).
StartOutcome cut_in_box(const ColorView& frame, const cv::Rect& box, double box_pixels,
                        cv::Size out_size, CutWorkspace& ws, WorkBudget& budget, cv::Mat& inside) {
  const int width = frame.luma.width, height = frame.luma.height;
  const CutHypothesis hypothesis = box_hypothesis(box, box_pixels);
  if (!pay(budget, problem_cost(hypothesis, width, height))) return StartOutcome::stopped();
  CutProblem problem;
  make_problem(frame, hypothesis, problem);
  if (std::string why = nothing_to_cut(problem); !why.empty())
    return StartOutcome::nothing("in the box, " + why);
  CutResult cut;
  if (!cut_object(problem, kBoxCut, ws, budget, cut)) return StartOutcome::stopped();
  if (!pay(budget, write_cost(problem, width, height, out_size))) return StartOutcome::stopped();
  write_cut(problem, cut, width, height, out_size, inside);
  if (cv::countNonZero(inside) == 0)
    return StartOutcome::nothing("in the box, nothing stands apart from its surroundings");
  return StartOutcome::cut();
}

}  // namespace

StartOutcome object_in_box(const ColorView& frame, const Rect& box_in, double box_pixels,
                           cv::Size out_size, CutWorkspace& ws, WorkBudget& budget,
                           cv::Mat& inside) {
  const cv::Rect whole(0, 0, frame.luma.width, frame.luma.height);
  cv::Rect box = cv::Rect(box_in.x, box_in.y, box_in.width, box_in.height) & whole;
  if (box.empty()) return StartOutcome::nothing("the box holds no pixel of the frame");
  // A box drawn within the object (nothing in it stands apart from the ring around it) is grown to
  // twice its sides, up to kGrowths times: the object overflows it.
  for (int growth = 0;; ++growth) {
    const StartOutcome out = cut_in_box(frame, box, box_pixels, out_size, ws, budget, inside);
    if (out.kind != StartOutcome::Kind::NothingToCut) return out;
    const cv::Rect grown =
        cv::Rect(box.x - box.width / 2, box.y - box.height / 2, 2 * box.width, 2 * box.height) &
        whole;
    if (growth == kGrowths || grown == box) return out;
    box = grown;
  }
}

}  // namespace projtrack
