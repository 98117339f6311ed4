// What projtrack-real writes: runs.csv (one row per clip, tracker and frame), speed.csv and
// meta.json (the run's settings, machine and clips).
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "clip.hpp"
#include "trackers.hpp"

namespace projtrack::bench {

// A pixel has changed when its luma differs by more than this many grey levels.
constexpr int kChangedLevels = 20;

class RunsCsv {
 public:
  explicit RunsCsv(const std::string& path);
  ~RunsCsv();
  bool ok() const { return f_ != nullptr; }
  void write(const Clip& c, const std::string& tracker, const std::string& group, int frame,
             const Report& r);

 private:
  std::FILE* f_;
};

void write_meta(const std::string& dir, const std::vector<std::unique_ptr<Clip>>& clips);

}  // namespace projtrack::bench
