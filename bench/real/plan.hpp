// prepare.py's plan of a run, as projtrack-real reads it: each clip or variant (an entry), the
// file it comes from, which frames and how they are changed; where its runs start.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "clip.hpp"

namespace projtrack::bench {

struct PlanEntry {
  std::string entry, clip, variant, source, kind;
  int start = 0, frames = 0, step = 1;  // frames: how many to keep (0: all)
  bool mirror = false;
  cv::Rect crop;
  double scale = 1;
  std::string lighting;  // a lighting, noise or speed variant of variants.hpp, or empty
};

// DIR/plan.csv's rows, in order.
std::vector<PlanEntry> read_plan(const std::string& dir);
// DIR/seeds.csv: each entry's starts.
std::map<std::string, Starts> read_starts(const std::string& dir);
// Whether the decoded frames are those the truth (DIR/truth/<entry>.csv) was labelled on: their
// mean luma follows the truth's through one affine map (limited or full range) to within 1.5
// levels on every frame. True when there is no truth to check against.
bool same_frames(const Clip& c, const std::string& truth_csv);

// The clip an entry shows, made from its source clip's decoded frames (all of them): the frames
// from `start`, every `step`-th, mirrored, cropped, scaled, then lit as `lighting` says.
std::unique_ptr<Clip> make_entry(const Clip& source, const PlanEntry& e);

}  // namespace projtrack::bench
