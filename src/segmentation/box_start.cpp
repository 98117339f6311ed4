#include "segmentation/box_start.hpp"

#include <algorithm>
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

BoxStart object_in_box(const WorkImages& img, const Rect& work_box, cv::Mat& inside) {
  const cv::Rect frame(0, 0, img.gray.cols, img.gray.rows);
  const cv::Rect box = cv::Rect(work_box.x, work_box.y, work_box.width, work_box.height) & frame;
  inside = cv::Mat::zeros(img.gray.size(), CV_8U);
  if (box.empty()) return BoxStart::Ellipse;
  const int gx = static_cast<int>(kContext * box.width);
  const int gy = static_cast<int>(kContext * box.height);
  const cv::Rect roi =
      cv::Rect(box.x - gx, box.y - gy, box.width + 2 * gx, box.height + 2 * gy) & frame;
  cv::Mat object;
  if (cut_in_box(img.bgr(roi), box - roi.tl(), object) &&
      cv::countNonZero(object) >= kCollapsed * box.area()) {
    object.copyTo(inside(roi));
    return BoxStart::Cut;
  }
  cv::ellipse(inside, (box.tl() + box.br()) / 2, box.size() / 2, 0, 0, 360, 255, cv::FILLED);
  return BoxStart::Ellipse;
}

}  // namespace projtrack
