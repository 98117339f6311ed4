// Follows several objects at once, each with its id: every object has its own model, status,
// loss and recovery (as a Tracker's), and one frame's evidence serves them all — its edges and
// its work images are made once, and its work budget is shared, so that N objects cannot take
// more than one frame's bound. Where two objects' silhouettes claim the same pixels, they go to
// the object whose model explains them better (the one in front); an object hidden that way is
// reported TrackStatus::Occluded with its last features, and is found again when it comes out.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "color_view.hpp"
#include "edge_detection.hpp"
#include "geometry.hpp"
#include "image_view.hpp"
#include "method.hpp"
#include "params.hpp"
#include "settings.hpp"
#include "silhouette_mask.hpp"
#include "trace.hpp"
#include "tracker.hpp"
#include "tracker_params.hpp"

namespace projtrack {

// What add() made of a start: the new object's id, or why there is none.
struct Added {
  int id = 0;       // from 1; 0: refused
  std::string why;  // when refused
  explicit operator bool() const { return id > 0; }
};

class MultiTracker {
 public:
  // At most `max_objects` objects at once (1 or more; 0 is taken as 1).
  explicit MultiTracker(std::size_t max_objects = 8);
  ~MultiTracker();
  MultiTracker(MultiTracker&&) noexcept;
  MultiTracker& operator=(MultiTracker&&) noexcept;

  // A new object in frames of width × height, tracked from the next frame on: from a point
  // inside it, a box around it, or its mask (non-zero on it, the frame's size). Refused (id 0,
  // with why) when the start lies outside the frame or is empty, when max_objects are followed,
  // or when it lies on an object followed already (two starts on one object).
  Added add_point(Point2i p, int width, int height);
  Added add_box(const Rect& box, int width, int height);
  Added add_mask(const ImageView& mask);
  // Stops following object `id`; false when there is none of that id.
  bool remove(int id);
  // Stops following every object (ids go on from where they were).
  void clear();

  std::size_t size() const;
  std::size_t max_objects() const;
  // The ids followed, in the order they were added.
  std::vector<int> ids() const;
  // Whether object `id` is followed.
  bool contains(int id) const;
  // Object `id`'s silhouette after the last frame (empty when there is none: see
  // Tracker::silhouette()). A view into the tracker.
  SilhouetteMask silhouette(int id) const;

  // As Tracker's, for every object.
  void set_stop_flag(const std::atomic<bool>* stop);
  void rescale(int width, int height, int new_width, int new_height);
  void relearn();

  // One frame taken at `t` seconds: one result per object followed, in the order of ids(), each
  // with its id. A frame that cannot be used gives every object its status (EmptyImage, ...).
  std::vector<TrackResult> track(const ColorView& frame, double t, const Settings& s,
                                 Trace* trace = nullptr);
  std::vector<TrackResult> track(const ImageView& gray, double t, const Settings& s,
                                 Trace* trace = nullptr);
  std::vector<TrackResult> track(const ColorView& frame, const EdgeParams& edge_params, double t,
                                 Method m, const Params& params, const TrackerParams& tp,
                                 Trace* trace = nullptr);
  std::vector<TrackResult> track(const ImageView& gray, const EdgeParams& edge_params, double t,
                                 Method m, const Params& params, const TrackerParams& tp,
                                 Trace* trace = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace projtrack
