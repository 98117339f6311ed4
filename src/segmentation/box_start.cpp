#include "segmentation/box_start.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

constexpr int kRounds = 3;        // GrabCut's iterations: its result settles by then
constexpr double kContext = 0.5;  // the surroundings read: the box grown by this share a side

}  // namespace

bool object_in_box(const WorkImages& img, const Rect& work_box, cv::Mat& inside) {
  const cv::Rect frame(0, 0, img.gray.cols, img.gray.rows);
  const cv::Rect box = cv::Rect(work_box.x, work_box.y, work_box.width, work_box.height) & frame;
  inside = cv::Mat::zeros(img.gray.size(), CV_8U);
  if (box.empty()) return false;
  const int gx = static_cast<int>(kContext * box.width),
            gy = static_cast<int>(kContext * box.height);
  const cv::Rect roi =
      cv::Rect(box.x - gx, box.y - gy, box.width + 2 * gx, box.height + 2 * gy) & frame;
  cv::Mat labels, bgd, fgd;
  bool cut = false;
  if (box.width >= 4 && box.height >= 4 && box.area() < roi.area()) {
    try {
      cv::grabCut(img.bgr(roi), labels, box - roi.tl(), bgd, fgd, kRounds, cv::GC_INIT_WITH_RECT);
      cv::Mat object = (labels & 1) != 0;
      cut = cv::countNonZero(object) > 0;
      if (cut) object.copyTo(inside(roi));
    } catch (const cv::Exception&) {
      cut = false;  // one colour in and around the box: no mixture to learn
    }
  }
  if (!cut)
    cv::ellipse(inside, (box.tl() + box.br()) / 2, box.size() / 2, 0, 0, 360, 255, cv::FILLED);
  return cut;
}

}  // namespace projtrack
