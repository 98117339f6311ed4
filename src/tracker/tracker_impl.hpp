// Tracker's hidden part, shared by the files of src/tracker/: one object's track
// (object_track.hpp) and the buffers of one frame's work (FrameWork), which a MultiTracker shares
// between its objects.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <string>

#include "core/mask.hpp"
#include "edges/edge_source.hpp"
#include "models/frame_evidence.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "tracker/object_track.hpp"

namespace projtrack {

// The buffers of one frame's work: nothing in them means anything once the frame is done.
struct FrameWork {
  EdgeMap edge_map;
  std::array<std::unique_ptr<Estimator>, kMethodCount> estimators;  // made on first use
  WorkBudget budget;                 // this frame's: every stage spends from it
  FrameEvidence::ImageSlots images;  // the frame at working scales (FrameEvidence::images)

  Estimator& estimator(Method m);
};

// Why a frame cannot be tracked at all (empty: it can): an unusable frame, or settings that
// cannot work (`status`: which). Said at once, on every frame, never searched with.
std::string frame_problem(const ColorView& frame, EdgeSource& edges, const FrameInput& in,
                          const WorkBudget& budget, TrackStatus& status);
// The model every object of a frame is followed with: an edge map given as the frame
// (EdgeDetector::Input) shows no appearance, so the edges model; else the settings'.
ObjectModelKind model_for(const EdgeSource& edges, const TrackerParams& tp);

struct Tracker::Impl {
  ObjectTrack object;
  FrameWork work;
  const std::atomic<bool>* stop = nullptr;
  int width = 0, height = 0;  // the last frame's size (Tracker::silhouette())

  // One frame (tracker.cpp): its budget, its checks, then the object's step.
  TrackResult track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
  TrackResult check_and_track(const ColorView& frame, EdgeSource& edges, const FrameInput& in);
};

}  // namespace projtrack
