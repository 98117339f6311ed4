// One stream of numpy frames as a Python tracker (Tracker or MultiTracker) takes it: read, timed,
// counted, one frame at a time, and followed through a change of size or kind as the element
// follows new caps. Both classes hold one, so that they read and time frames alike.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <mutex>

#include "frames.hpp"

namespace projtrack::python {

class FrameStream {
 public:
  explicit FrameStream(double fps) : fps_(fps) {}

  // The stream to oneself: waits for another thread's frame without the GIL, which that thread
  // needs to finish (the tracker runs without it).
  std::unique_lock<std::mutex> lock();
  // `frame` as the library reads it, valid until the next read (FrameReader::read).
  ColorView read(const pybind11::handle& frame) { return reader_.read(frame); }
  // The next frame's time: `t` seconds when given (a finite number), else the frames counted so
  // far at the fps, from 0 when `restart`.
  double seconds(const pybind11::object& t, bool restart) const;
  // The last frame read, of width × height, given to `tracker` (a Tracker or a MultiTracker) after
  // the frame before: as the element takes new caps (gst/stream.cpp, set_info()), another size
  // rescales its objects, another kind of frame at the same size (gray, BGR, BGRA: another format)
  // relearns their colours.
  template <class T>
  void follow(T& tracker, int width, int height) {
    const int channels = reader_.channels();
    if (width_ > 0 && (width != width_ || height != height_))
      tracker.rescale(width_, height_, width, height);
    else if (channels_ > 0 && channels != channels_)
      tracker.relearn();
    width_ = width;
    height_ = height;
    channels_ = channels;
  }
  // The last frame's size (0 before any).
  int width() const { return width_; }
  int height() const { return height_; }
  void count() { ++frames_; }
  void restart() { frames_ = 0; }
  // Frames tracked since the start or restart(); read while a thread tracks.
  long frames() const { return frames_; }

 private:
  double fps_;
  FrameReader reader_;
  int width_ = 0, height_ = 0, channels_ = 0;  // the last frame's (0: none yet)
  std::mutex mutex_;                           // one frame at a time: the tracker runs without GIL
  std::atomic<long> frames_{0};
};

}  // namespace projtrack::python
