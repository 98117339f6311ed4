// Per-pixel routines on whole frames against OpenCV's, each into buffers made once, as the
// element calls them frame after frame: see cases.hpp.
#include <opencv2/imgproc.hpp>

#include "cases.hpp"
#include "edges/box_blur.hpp"
#include "edges/canny.hpp"
#include "projtrack/color_conversion.hpp"
#include "projtrack/edge_detection.hpp"

namespace projtrack::handwritten {

std::string same_pixels(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return "no (different shapes)";
  const int differ = cv::countNonZero(a.reshape(1) != b.reshape(1));
  if (differ == 0) return "yes";
  return "no (" + std::to_string(differ) + " of " + std::to_string(a.total() * a.channels()) +
         " values differ)";
}

namespace {

ImageView view(const cv::Mat& m) {
  return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
}

cv::Mat mat(const ImageView& v) {
  return cv::Mat(v.height, v.width, CV_8U, const_cast<std::uint8_t*>(v.data),
                 static_cast<std::size_t>(v.stride));
}

void edges(const Frame& f, const Effort& e, std::FILE* out) {
  cv::Mat ours(f.height, f.width, CV_8U), theirs(f.height, f.width, CV_8U);
  Row r{"3x3 box blur", "src/edges/box_blur.cpp box_blur3",
        "cv::blur 3x3 BORDER_REPLICATE + BORDER_ISOLATED", f.name + " luma, whole frame", ""};
  const Duel blur = duel(
      [&] {
        box_blur3(view(f.luma), {0, 0, f.width, f.height}, ours.data, ours.step);
      },
      [&] {
        // Isolated: the luma plane is a view of the I420 buffer, whose chroma follows it.
        cv::blur(f.luma, theirs, {3, 3}, {-1, -1}, cv::BORDER_REPLICATE | cv::BORDER_ISOLATED);
      },
      e.rounds, e.calls);
  r.same = same_pixels(ours, theirs);
  write_row(out, r, blur);

  const EdgeParams ep;
  const cv::Mat blurred = theirs.clone();
  CannyDetector canny;
  cv::Mat cv_edges(f.height, f.width, CV_8U);
  ImageView our_edges;
  r = {"Canny (3x3 Sobel, L1, hysteresis)", "src/edges/canny.cpp CannyDetector",
       "cv::Canny 50/150 aperture 3 L1", f.name + " blurred luma, whole frame", ""};
  const Duel c =
      duel([&] { our_edges = canny.detect(view(blurred), ep.low, ep.high); },
           [&] { cv::Canny(blurred, cv_edges, ep.low, ep.high, 3, false); }, e.rounds, e.calls);
  r.same = same_pixels(mat(our_edges), cv_edges);
  write_row(out, r, c);
}

void colour_conversions(const Frame& f, const Effort& e, std::FILE* out) {
  const std::uint8_t* p = f.rgb.data;
  const auto stride = static_cast<std::ptrdiff_t>(f.rgb.step);
  // Ours and OpenCV's I420 share the video-range luma (rounded alike or not: compared); the
  // chroma differs by design (ours each 2x2 block's mean, OpenCV's its top-left pixel).
  std::vector<std::uint8_t> planes;
  cv::Mat i420;
  Row r{"packed RGB to luma and chroma (BT.601, video range, 4:2:0)",
        "src/edges/color_conversion.cpp packed_rgb_to_color", "cv::cvtColor RGB2YUV_I420",
        f.name + " RGB", ""};
  const Duel g =
      duel([&] { packed_rgb_to_color(p, p + 1, p + 2, 3, stride, f.width, f.height, planes); },
           [&] { cv::cvtColor(f.rgb, i420, cv::COLOR_RGB2YUV_I420); }, e.rounds, e.calls);
  const cv::Mat our_luma(f.height, f.width, CV_8U, planes.data());
  r.same = "luma " + same_pixels(our_luma, i420.rowRange(0, f.height)) +
           "; chroma not compared (block mean against top-left pixel)";
  write_row(out, r, g);

  // YUY2: luma in every second byte (the chroma here neutral: only the luma is gathered).
  cv::Mat yuy2(f.height, f.width, CV_8UC2, cv::Scalar(0, 128));
  cv::insertChannel(f.luma, yuy2, 0);
  cv::Mat luma(f.height, f.width, CV_8U), cv_luma(f.height, f.width, CV_8U);
  r = {"packed YUV's luma into a plane", "src/edges/color_conversion.cpp gather_component",
       "cv::cvtColor YUV2GRAY_YUY2", f.name + " YUY2", ""};
  const Duel y = duel(
      [&] { gather_component(yuy2.data, 2, yuy2.step, f.width, f.height, luma.data, luma.step); },
      [&] { cv::cvtColor(yuy2, cv_luma, cv::COLOR_YUV2GRAY_YUY2); }, e.rounds, e.calls);
  r.same = same_pixels(luma, cv_luma);
  write_row(out, r, y);
}

}  // namespace

void pixel_duels(const std::vector<Frame>& frames, const Effort& e, std::FILE* out) {
  for (const Frame& f : frames) {
    edges(f, e, out);
    colour_conversions(f, e, out);
  }
}

}  // namespace projtrack::handwritten
