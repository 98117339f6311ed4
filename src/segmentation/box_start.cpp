#include "segmentation/box_start.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "segmentation/grab_cut.hpp"

namespace projtrack {

namespace {

// GrabCut's iterations: its result settles by then (davis-dev from the box: 3 took libby's first
// silhouette to 69 IoU, 5, 7 and 10 to 77; the rest the same).
constexpr int kRounds = 5;
constexpr double kContext = 0.5;  // the surroundings read: the box grown by this share a side
// GrabCut has collapsed when it keeps less than this share of the box: on a thin dancer or a
// small car in smoke it can take nothing at all (davis-dev at the working scale). The box's
// colours against its ring's instead of the ellipse measured no better there (J 46.5 against
// 47.5 from the box: dance-twirl better, drift-chicane worse).
constexpr double kCollapsed = 0.05;

// GrabCut's object in `box` (ROI coordinates), into `object`; false when it cannot run. The
// object is probable in the ellipse inscribed in the box, its corners probable background: a box
// drawn around an object holds its surroundings in the corners (a kite's lines, a cow's legs
// apart), and with the whole box probable the object's first mixture learned them as its own
// (davis-dev from the box, J 48.8 -> 49.6: cows +1.7, libby +4.6, the rest within a point).
bool cut_in_box(const cv::Mat& bgr, const cv::Rect& box, cv::Mat& object) {
  if (box.width < 4 || box.height < 4 || box.area() >= bgr.rows * bgr.cols) return false;
  cv::Mat labels(bgr.size(), CV_8U, cv::Scalar(cv::GC_BGD));
  labels(box).setTo(cv::GC_PR_BGD);
  cv::ellipse(labels, (box.tl() + box.br()) / 2, box.size() / 2, 0, 0, 360, cv::GC_PR_FGD,
              cv::FILLED);
  if (!grab_cut(bgr, labels, cv::Rect(), kRounds)) return false;
  object = (labels & 1) != 0;
  return true;
}

}  // namespace

BoxStart object_in_box(const cv::Mat& bgr, const Rect& box_in, cv::Mat& inside) {
  const cv::Rect frame(0, 0, bgr.cols, bgr.rows);
  const cv::Rect box = cv::Rect(box_in.x, box_in.y, box_in.width, box_in.height) & frame;
  inside = cv::Mat::zeros(bgr.size(), CV_8U);
  if (box.empty()) return BoxStart::Ellipse;
  const int gx = static_cast<int>(kContext * box.width);
  const int gy = static_cast<int>(kContext * box.height);
  const cv::Rect roi =
      cv::Rect(box.x - gx, box.y - gy, box.width + 2 * gx, box.height + 2 * gy) & frame;
  cv::Mat object;
  if (cut_in_box(bgr(roi), box - roi.tl(), object) &&
      cv::countNonZero(object) >= kCollapsed * box.area()) {
    object.copyTo(inside(roi));
    return BoxStart::Cut;
  }
  cv::ellipse(inside, (box.tl() + box.br()) / 2, box.size() / 2, 0, 0, 360, 255, cv::FILLED);
  return BoxStart::Ellipse;
}

void cuts_vote(const std::array<cv::Mat, 3>& votes, const std::array<BoxStart, 3>& how,
               cv::Mat& inside) {
  // An ellipse that outvoted the one cut of a thin dancer among spectators held them for good
  // (davis-dev's dance-twirl from the box: J 54.5 -> 63.2).
  const auto cuts = std::count(how.begin(), how.end(), BoxStart::Cut);
  const int voters = cuts == 0 ? static_cast<int>(votes.size()) : static_cast<int>(cuts);
  cv::Mat count = cv::Mat::zeros(votes[0].size(), CV_8U);
  for (std::size_t i = 0; i < votes.size(); ++i)
    if (cuts == 0 || how[i] == BoxStart::Cut) count += votes[i] / 255;
  cv::compare(count, (voters - 1) / 2, inside, cv::CMP_GT);
}

BoxStart object_in_box(const cv::Mat& frame, const Rect& box, double box_pixels, cv::Size work_size,
                       cv::Mat& inside) {
  constexpr int kCuts = 3;
  const double area = std::max(1.0, static_cast<double>(box.width) * box.height);
  std::array<cv::Mat, kCuts> votes;
  std::array<BoxStart, kCuts> how{};
  // The cuts are independent (GrabCut's seed is the thread's own): OpenCV's threads share them.
  cv::parallel_for_(cv::Range(0, kCuts), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const double k = std::min(1.0, std::sqrt(box_pixels * std::ldexp(1.0, i - 1) / area));
      cv::Mat bgr, cut;
      cv::resize(frame, bgr, {}, k, k, cv::INTER_AREA);
      const Rect at{static_cast<int>(std::lround(box.x * k)),
                    static_cast<int>(std::lround(box.y * k)),
                    static_cast<int>(std::lround(box.width * k)),
                    static_cast<int>(std::lround(box.height * k))};
      how[i] = object_in_box(bgr, at, cut);
      // Its share of each work pixel, then a vote where it covers more than half.
      cv::resize(cut, votes[i], work_size, 0, 0, cv::INTER_AREA);
      cv::compare(votes[i], 127, votes[i], cv::CMP_GT);
    }
  });
  cuts_vote(votes, how, inside);
  if (cv::countNonZero(inside) == 0) votes[1].copyTo(inside);  // cuts apart: the middle one
  if (cv::countNonZero(inside) == 0 && box.width > 0 && box.height > 0) {
    // A box under a work pixel or two: its ellipse at the working size, at least a pixel.
    const double sx = static_cast<double>(work_size.width) / frame.cols;
    const double sy = static_cast<double>(work_size.height) / frame.rows;
    const cv::Point centre(static_cast<int>((box.x + box.width / 2.0) * sx),
                           static_cast<int>((box.y + box.height / 2.0) * sy));
    const cv::Size axes(static_cast<int>(box.width * sx / 2),
                        static_cast<int>(box.height * sy / 2));
    cv::ellipse(inside, centre, axes, 0, 0, 360, 255, cv::FILLED);
  }
  return std::count(how.begin(), how.end(), BoxStart::Cut) > 0 ? BoxStart::Cut : BoxStart::Ellipse;
}

}  // namespace projtrack
