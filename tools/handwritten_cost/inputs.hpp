// The inputs every duel is given, as the project's own calls get them: a real colour frame (a
// frame of opencv-doc's Megamind.avi, scaled) in the forms the element reads, and a real-looking
// mask (the synthetic hand) at the scales the object model and the finder work at.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/mask.hpp"
#include "projtrack/color_view.hpp"

namespace projtrack::handwritten {

// One frame as the element gets it: packed RGB (and BGR for OpenCV), and I420 planes.
struct Frame {
  std::string name;  // "640x480"
  int width = 0, height = 0;
  cv::Mat rgb, bgr;  // CV_8UC3
  cv::Mat i420;      // the whole I420 buffer: height × 3/2 rows of width bytes
  cv::Mat luma;      // its Y plane (a view)
  cv::Mat u, v;      // its chroma planes, half resolution (views)
  ColorView color() const;
};

// Frame `index` of `clip` scaled to w × h; a generated gray scene if the clip cannot be read.
Frame real_frame(const std::string& clip, int index, int w, int h);

// A mask (CV_8U, 0 or 1) and what it stands for.
struct MaskInput {
  std::string name;
  cv::Mat mask;
};

// The hand (synthetic/, filled) as the whole frame at the flow model's working scale holds it for
// a 640×480 and a 1920×1080 frame (FlowModelParams::work_pixels), as its region at the object's
// own scale holds it (FlowModelParams::object_pixels), and at the full resolution of a 1920×1080
// frame.
std::vector<MaskInput> hand_masks();

// `m` (0 or non-zero) as a Mask at (0, 0).
void to_mask(const cv::Mat& m, Mask& out);
// `m` as a cv::Mat of 0 and 1 (a copy).
cv::Mat to_mat(const Mask& m);

}  // namespace projtrack::handwritten
