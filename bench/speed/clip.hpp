// The frames every contender of projtrack-speed is given, in every form it needs: generated
// (a sphere with exact truth), real (opencv-doc's clip) and adversarial (bounded-work sections).
#pragma once

#include <gst/gst.h>

#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "adversarial.hpp"
#include "projtrack/geometry.hpp"

namespace projtrack::bench {

// The same frames in every form a contender needs.
struct Clip {
  std::string name;
  int width = 0, height = 0;
  std::vector<cv::Mat> gray;          // CV_8U
  std::vector<GstBuffer*> i420, rgb;  // what projtrack and cvtracker are given
  std::vector<Point2i> seeds;         // an inner point per frame (the truth when known)
  Rect first_box;                     // the object's box on frame 0 (cvtracker's start)
  double object_share = 0;            // object area / frame area on frame 0 (0: unknown)
  ~Clip() {
    for (GstBuffer* b : i420) gst_buffer_unref(b);
    for (GstBuffer* b : rgb) gst_buffer_unref(b);
  }
};

// Appends one frame, given as BGR or gray, in every form of Clip.
void add_frame(Clip& c, const cv::Mat& bgr_or_gray);

// A sphere covering about `share` of the frame, swinging left and right by `swing` of the frame's
// width (a period of `n` frames, so looping over the frames is smooth motion), fresh sensor
// noise on each frame.
std::unique_ptr<Clip> generated_clip(int w, int h, double share, int n, double swing = 0.12);

// A real clip (opencv-doc's Megamind.avi: an animated character on a busy background), resized.
// The object is unknown: projtrack finds one by itself (acquisition=auto), the stock-OpenCV
// peer fills from the frame centre, cvtracker starts from a centred box a tenth of the frame.
std::unique_ptr<Clip> real_clip(const std::string& path, int w, int h, int max_frames);

// `n` frames of one of the adversarial scenes (synthetic/adversarial.hpp), seeded at the centre.
std::unique_ptr<Clip> adversarial_clip(const synthetic::AdversaryInfo& a, int w, int h, int n);

}  // namespace projtrack::bench
