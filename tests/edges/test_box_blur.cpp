// The box blur must equal cv::blur (3×3, BORDER_REPLICATE), and a region's blur must equal the
// whole image's blur cropped: the tracker blurs regions and promises the frame's answers.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "edges/box_blur.hpp"

namespace projtrack {
namespace {

ImageView view(const cv::Mat& m) {
  return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
}

cv::Mat reference(const cv::Mat& img) {
  cv::Mat out;
  cv::blur(img, out, {3, 3}, {-1, -1}, cv::BORDER_REPLICATE);
  return out;
}

TEST(BoxBlur, EqualsOpenCVsBlurForEverySizeFromOnePixel) {
  cv::RNG rng(11);
  for (int i = 0; i < 300; ++i) {
    const int w = rng.uniform(1, 80), h = rng.uniform(1, 60);
    cv::Mat img(h, w, CV_8UC1);
    rng.fill(img, cv::RNG::UNIFORM, 0, 256);
    cv::Mat out(h, w, CV_8UC1);
    box_blur3(view(img), Rect{0, 0, w, h}, out.data, static_cast<std::ptrdiff_t>(out.step));
    ASSERT_EQ(cv::countNonZero(out != reference(img)), 0) << w << "×" << h;
  }
}

TEST(BoxBlur, SaturatedAndBlackImagesStayExact) {
  for (int v : {0, 1, 254, 255}) {
    const cv::Mat img(9, 9, CV_8UC1, cv::Scalar(v));
    cv::Mat out(9, 9, CV_8UC1);
    box_blur3(view(img), Rect{0, 0, 9, 9}, out.data, 9);
    EXPECT_EQ(cv::countNonZero(out != v), 0) << v;
  }
}

TEST(BoxBlur, ARegionIsTheWholeBlurCropped) {
  cv::RNG rng(5);
  cv::Mat img(70, 5000, CV_8UC1);  // wider than one 4096-column chunk
  rng.fill(img, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat whole = reference(img);
  for (const Rect r : {Rect{0, 0, 5000, 70}, Rect{1, 1, 4998, 68}, Rect{4000, 10, 1000, 30},
                       Rect{0, 69, 1, 1}, Rect{4999, 0, 1, 70}, Rect{17, 3, 4500, 1}}) {
    cv::Mat out(r.height, r.width, CV_8UC1);
    box_blur3(view(img), r, out.data, static_cast<std::ptrdiff_t>(out.step));
    EXPECT_EQ(cv::countNonZero(out != whole(cv::Rect(r.x, r.y, r.width, r.height))), 0)
        << r.x << "," << r.y << " " << r.width << "×" << r.height;
  }
}

}  // namespace
}  // namespace projtrack
