// The duels' inputs: see inputs.hpp.
#include "inputs.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/work_scale.hpp"
#include "projtrack/flow_model_params.hpp"
#include "scene.hpp"

namespace projtrack::handwritten {

ColorView Frame::color() const {
  ColorView c;
  c.luma = ImageView(luma.data, width, height, static_cast<std::ptrdiff_t>(luma.step));
  c.chroma.u = u.data;
  c.chroma.v = v.data;
  c.chroma.stride = static_cast<std::ptrdiff_t>(u.step);
  c.chroma.shift_x = c.chroma.shift_y = 1;
  return c;
}

Frame real_frame(const std::string& clip, int index, int w, int h) {
  cv::Mat bgr;
  cv::VideoCapture cap(clip);
  for (int i = 0; i <= index && cap.isOpened(); ++i)
    if (!cap.read(bgr)) break;
  if (bgr.empty())  // no clip: a generated scene (gray, so the chroma is neutral)
    cv::cvtColor(synthetic::make_scene(synthetic::SceneSpec(w, h), {}).image, bgr,
                 cv::COLOR_GRAY2BGR);
  Frame f;
  f.name = std::to_string(w) + "x" + std::to_string(h);
  f.width = w;
  f.height = h;
  cv::resize(bgr, f.bgr, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
  cv::cvtColor(f.bgr, f.rgb, cv::COLOR_BGR2RGB);
  cv::cvtColor(f.bgr, f.i420, cv::COLOR_BGR2YUV_I420);
  f.luma = f.i420.rowRange(0, h);
  // I420's chroma planes follow the luma, each (w/2) × (h/2) bytes, rows w/2 apart.
  f.u = cv::Mat(h / 2, w / 2, CV_8U, f.i420.ptr(h));
  f.v = cv::Mat(h / 2, w / 2, CV_8U, f.i420.ptr(h) + (w / 2) * (h / 2));
  return f;
}

namespace {

// The hand's mask of a w × h frame, shrunk to `pixels` work pixels of the region `r` of it.
MaskInput shrunk(const std::string& name, const cv::Mat& hand, const cv::Rect& r, double pixels) {
  const int s = work_scale(static_cast<double>(r.width) * r.height, pixels);
  cv::Mat small;
  cv::resize(hand(r), small, cv::Size((r.width + s - 1) / s, (r.height + s - 1) / s), 0, 0,
             cv::INTER_AREA);
  return {name + " (scale " + std::to_string(s) + ": " + std::to_string(small.cols) + "x" +
              std::to_string(small.rows) + ")",
          small >= 128};
}

cv::Mat hand_at(int w, int h) {
  return synthetic::make_scene(synthetic::SceneSpec(w, h, synthetic::Object::Hand), {}).mask;
}

}  // namespace

std::vector<MaskInput> hand_masks() {
  std::vector<MaskInput> out;
  const cv::Mat vga = hand_at(640, 480), hd = hand_at(1920, 1080);
  const FlowModelParams flow;
  out.push_back(shrunk("work frame of 640x480", vga, {0, 0, 640, 480}, flow.work_pixels));
  out.push_back(shrunk("work frame of 1920x1080", hd, {0, 0, 1920, 1080}, flow.work_pixels));
  // The object at its own scale: the hand's box and as much again around it.
  const cv::Rect box = cv::boundingRect(hd);
  const cv::Rect region =
      cv::Rect(box.x - box.width / 2, box.y - box.height / 2, box.width * 2, box.height * 2) &
      cv::Rect(0, 0, 1920, 1080);
  out.push_back(shrunk("the object's region of 1920x1080", hd, region, 4 * flow.object_pixels));
  out.push_back({"full resolution 1920x1080", hd >= 128});
  for (MaskInput& m : out) m.mask &= 1;
  return out;
}

void to_mask(const cv::Mat& m, Mask& out) {
  out.reset({0, 0, m.cols, m.rows});
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) out.row(y)[x] = m.at<std::uint8_t>(y, x) ? 1 : 0;
}

cv::Mat to_mat(const Mask& m) {
  cv::Mat out(m.rect().height, m.rect().width, CV_8U);
  for (int y = 0; y < out.rows; ++y) std::copy_n(m.row(y), out.cols, out.ptr<std::uint8_t>(y));
  return out;
}

}  // namespace projtrack::handwritten
