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
  if (!pay(budget, write_cost(best_problem, width, height, out_size)))
    return StartOutcome::stopped();
  write_cut(best_problem, best, width, height, out_size, inside);
  return StartOutcome::cut();
}

}  // namespace projtrack
