// A clip of real footage as projtrack-real holds it: its decoded I420 frames (any size, odd ones
// too), the buffers each tracker is given, and where its runs start (from prepare.py's plan).
#pragma once

#include <gst/gst.h>

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "projtrack/geometry.hpp"

namespace projtrack::bench {

// One I420 frame as three planes; the chroma planes are ceil(h / 2) × ceil(w / 2).
struct I420Frame {
  cv::Mat y, u, v;
  I420Frame clone() const { return {y.clone(), u.clone(), v.clone()}; }
};

// Where the runs on a clip start (the first frame's true silhouette; seeds.csv).
struct Starts {
  std::optional<Point2i> deepest;
  std::vector<Point2i> quarters;
  std::optional<Rect> box;
};

struct Clip {
  std::string name;     // the entry: "cup", "cup-edge", ...
  std::string variant;  // empty for the clip as decoded
  std::string path;     // the file (or pgm pattern) it was decoded from
  int width = 0, height = 0, fps_n = 30, fps_d = 1;
  std::vector<I420Frame> frames;
  std::vector<GstClockTime> pts;
  Starts starts;  // none: no truth, the clip runs without a seed only
  std::vector<GstBuffer*> i420_buffers, rgb_buffers;

  Clip() = default;
  Clip(const Clip&) = delete;
  Clip& operator=(const Clip&) = delete;
  ~Clip();
  bool has_truth() const { return starts.deepest.has_value(); }
  const cv::Mat& luma(int i) const { return frames[i].y; }
  // The per-pixel median luma of up to 99 frames spread over the clip: the scene's background.
  const cv::Mat& median_luma() const;
  std::string caps(const char* format) const;
  // Frees the frames, their buffers and the median once the clip's runs are done; what meta.json
  // says of it (name, size, frame count: pts) stays.
  void release_frames();

 private:
  mutable cv::Mat median_;
};

// Decodes a clip as a user's pipeline would, into I420: a file through `filesrc ! decodebin !
// videoconvert` (kind "video"); a pgm sequence (kind "pgm": `path` is the pattern of its sorted
// images) read with OpenCV (the raw GRAY8 pixels pnmdec gives) through `videoconvert`; a file
// GStreamer 1.22 cannot demux (kind "opencv": VP9 in AVI, which avidemux leaves as
// video/x-avi-unknown) read by OpenCV's FFmpeg reader, BGR through `videoconvert`. Up to
// `max_frames` (0: all).
bool decode(const std::string& path, const std::string& kind, Clip& c, int max_frames);
// Fills the buffers each tracker is given (I420 for projtrack, RGB for cvtracker), in
// GStreamer's default layout for the clip's size.
void make_buffers(Clip& c);
// The frame as BGR (OpenCV's BT.601 conversion; odd sizes padded, then cropped back).
cv::Mat to_bgr(const I420Frame& f);
// An even-sized BGR image as an I420 frame.
I420Frame from_bgr(const cv::Mat& bgr);
// A buffer holding the frame in GStreamer's default I420 layout.
GstBuffer* i420_buffer(const I420Frame& f, GstClockTime pts, GstClockTime duration);

}  // namespace projtrack::bench
