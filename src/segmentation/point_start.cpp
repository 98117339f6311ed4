#include "segmentation/point_start.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "segmentation/cut_pieces.hpp"
#include "segmentation/cut_problem.hpp"
#include "segmentation/start_work.hpp"

namespace projtrack {

namespace {

constexpr int kSquares = 9;
constexpr double kSmallest = 0.02, kLargest = 1.0;  // half-sides, of the frame's smaller side
constexpr double kCore = 0.5;     // the object expected within this share of the half-side
constexpr double kContext = 1.0;  // the surroundings: the square grown by its side a side
constexpr double kCoarseCells = 400, kFineCells = 4000;
constexpr int kFinalists = 2;
constexpr CutSettings kCoarse{2, false, 2};
constexpr CutSettings kFine{2, true, 2};

// An outline scoring less (its contrast × the share of it that is not the square's edge) is no
// object's: davis-dev's clicks scored 0.58-0.77, a patch of a flat wall in the frame's corner
// 0.25 (half its outline the frame's edge).
constexpr double kLeastScore = 0.35;
// A cut that reaches this many of the frame's sides is the background around the things in view
// (a wall, a table), not an object the user points at; and so is one that reaches two and whose
// outline lies this much on the square's edge (it goes on past the square: davis-dev's objects
// 0.03 at most, a wall by the frame's corner beside a disc 0.32).
constexpr int kBackgroundSides = 3;
constexpr double kBackgroundTouch = 0.25;

// How many of its four sides `mask` (CV_8U) reaches.
int frame_sides_touched(const cv::Mat& mask) {
  if (mask.empty()) return 0;
  const int last_row = mask.rows - 1, last_col = mask.cols - 1;
  return (cv::countNonZero(mask.row(0)) > 0) + (cv::countNonZero(mask.row(last_row)) > 0) +
         (cv::countNonZero(mask.col(0)) > 0) + (cv::countNonZero(mask.col(last_col)) > 0);
}

struct Square {
  double score = -1;  // the outline's: contrast × (1 - touch)
  int half = 0;
};

CutHypothesis square_hypothesis(const Point2i& point, int half, double cells, int width,
                                int height) {
  CutHypothesis h;
  h.box = cv::Rect(point.x - half, point.y - half, 2 * half + 1, 2 * half + 1) &
          cv::Rect(0, 0, width, height);
  h.point = &point;
  h.pixels = cells;
  h.context = kContext;
  h.centre = {point.x + 0.5, point.y + 0.5};
  h.radii = {kCore * half, kCore * half};
  return h;
}

// The square of `half` cut at `cells` with `settings` into `problem` and `cut`; its score, or -1
// when it holds nothing to cut. False when the budget stopped it.
bool cut_square(const ColorView& frame, const Point2i& point, int half, double cells,
                const CutSettings& settings, CutWorkspace& ws, WorkBudget& budget,
                CutProblem& problem, CutResult& cut, double& score) {
  const int width = frame.luma.width, height = frame.luma.height;
  const CutHypothesis h = square_hypothesis(point, half, cells, width, height);
  if (!pay(budget, problem_cost(h, width, height))) return false;
  make_problem(frame, h, problem);
  score = -1;
  if (!nothing_to_cut(problem).empty()) return true;
  if (!cut_object(problem, settings, ws, budget, cut)) return false;
  score = cut.contrast * (1 - cut.touch);
  return true;
}

}  // namespace

StartOutcome object_at_point(const ColorView& frame, Point2i point, cv::Size out_size,
                             CutWorkspace& ws, WorkBudget& budget, cv::Mat& inside) {
  const int width = frame.luma.width, height = frame.luma.height;
  if (!cv::Rect(0, 0, width, height).contains({point.x, point.y}))
    return StartOutcome::nothing("the point lies outside the frame");
  const double side = std::min(width, height);
  std::vector<Square> squares;
  CutProblem problem;
  CutResult cut;
  for (int k = 0; k < kSquares; ++k) {
    const double t = static_cast<double>(k) / (kSquares - 1);
    const int half = std::max(
        1, static_cast<int>(std::lround(kSmallest * side * std::pow(kLargest / kSmallest, t))));
    Square s;
    s.half = half;
    if (!cut_square(frame, point, half, kCoarseCells, kCoarse, ws, budget, problem, cut, s.score))
      return StartOutcome::stopped();
    if (s.score >= 0) squares.push_back(s);
  }
  if (squares.empty())
    return StartOutcome::nothing(
        "around the point, nothing to cut: no square around it holds "
        "colours apart from its surroundings'");
  // Best first; on a tie the smaller square.
  std::stable_sort(squares.begin(), squares.end(),
                   [](const Square& a, const Square& b) { return a.score > b.score; });
  CutProblem best_problem;
  CutResult best;
  double best_score = -1;
  // The best squares that still hold something to cut at the fine grain (a square whose coarse
  // cells blurred a small ball into its surroundings may not).
  int finalists = 0;
  for (std::size_t f = 0; f < squares.size() && finalists < kFinalists; ++f) {
    double score = -1;
    if (!cut_square(frame, point, squares[f].half, kFineCells, kFine, ws, budget, problem, cut,
                    score))
      return StartOutcome::stopped();
    if (score < 0) continue;
    ++finalists;
    if (score > best_score) {
      best_score = score;
      std::swap(best, cut);
      std::swap(best_problem, problem);
    }
  }
  if (best_score < 0)
    return StartOutcome::nothing("around the point, nothing to cut at the finer grain");
  if (best_score < kLeastScore)
    return StartOutcome::nothing(
        "under the point, nothing stands apart: the best outline around it is mostly the edge of "
        "the frame or of the square read, or no contrast");
  if (!pay(budget, write_cost(best_problem, width, height, out_size)))
    return StartOutcome::stopped();
  write_cut(best_problem, best, width, height, out_size, inside);
  const int sides = frame_sides_touched(inside);
  if (sides >= kBackgroundSides || (sides >= 2 && best.touch >= kBackgroundTouch))
    return StartOutcome::nothing(
        "under the point, what stands apart reaches the frame's edges and goes on past the "
        "squares read: the background, not an object");
  return StartOutcome::cut();
}

}  // namespace projtrack
