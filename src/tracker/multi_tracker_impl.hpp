// MultiTracker's hidden part: one ObjectTrack per object, and one frame's work (its edges, its
// work images, its budget) shared by them all (multi_frame.cpp).
#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include "projtrack/multi_tracker.hpp"
#include "tracker/tracker_impl.hpp"

namespace projtrack {

struct MultiTracker::Impl {
  struct Object {
    int id = 0;
    ObjectTrack track;
    // Hidden by another object (its id; 0: not hidden): the model looks for it by its colours
    // near where it was, and while it is not found where that object still covers it, it is
    // occluded.
    int hidden_by = 0;
    // Whether it gave pixels up to an object in front on the last frame, and its area before it
    // met that object: hidden is more than half of that area covered.
    bool met = false;
    double area_before_met = 0;
    std::uint64_t last_work = 0;  // the work it did on the last frame
  };
  std::vector<Object> objects;  // in the order they were added
  FrameWork work;
  std::size_t max_objects = 1;
  int next_id = 1;
  const std::atomic<bool>* stop = nullptr;
  int width = 0, height = 0;  // the last frame's size
  int patience = 0;           // the frame's TrackerParams::patience

  Object* find(int id);
  const Object* find(int id) const;
  // Why a start at `p` (with `box`, when it has one) cannot be a new object (empty: it can): too
  // many objects, or an object followed (or about to start) is there already.
  std::string why_not_new(Point2i p, const Rect* box, int width, int height) const;
  // The object added: its id.
  Added add(Object&& o);

  // One frame (multi_frame.cpp): its checks, then each object's look, the pixels two objects
  // claim given to the one in front, and each object's verdict.
  std::vector<TrackResult> track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  // The order objects look at a frame in, each within an equal share of what the objects before
  // it left of the frame's budget: followed objects by what they cost on the last frame, the
  // cheapest first (the frame's budget shared max-min fairly, as water fills vessels), then
  // starts, each with all that is left (a start costs most); the user's first start not taken
  // yet before them all.
  std::vector<std::size_t> look_order() const;
  // Where two looks' silhouettes meet, the pixels go to the object whose model explains them
  // better (the one in front; on a tie, the one added first); the other gives them up. The id of
  // the object in front of each object that lost more than half its area since it met it (0:
  // none): that object is hidden on this frame.
  std::vector<int> settle_overlaps(std::vector<Look>& looks);
  // Object `i`'s verdict on this frame: occluded when `hidden_by` (newly, or still where the
  // object in front covers it and not found), else the verdict of its look, a refusal being
  // occluded when object `covered_by` (0: none) covers it.
  TrackResult conclude(std::size_t i, int hidden_by, int covered_by, FrameEvidence& ev,
                       const FrameInput& in, const Look& look);
  // The id of an object `followed` on this frame (its silhouette there) that covers at least half
  // of object `i`'s last box (0: none).
  int covering(std::size_t i, const std::vector<bool>& followed) const;
  // Whether object `front` (an id) still covers where object `i` was last seen.
  bool still_covers(int front, std::size_t i) const;
};

}  // namespace projtrack
