// Contenders raced side by side: each processes the same frames in turn, batch after batch, the
// order rotated every round, so a noisy machine slows all of them alike.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "clip.hpp"

namespace projtrack::bench {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0);

// One contender: processes frame i of its clip (frames come in order, each contender has its own).
struct Contender {
  Contender(std::string n, std::function<void(int)> f)
      : name(std::move(n)), process(std::move(f)) {}
  std::string name;
  std::function<void(int)> process;
  std::size_t next = 0;
  std::vector<double> per_frame_us;  // one value per round: the batch's mean
};

double median(std::vector<double> v);

// The median over rounds of a's time / b's (each round's contenders ran back to back).
double median_ratio(const Contender& a, const Contender& b);

// Rounds of batches, the contenders' order rotated every round.
void race(std::vector<Contender>& cs, const Clip& clip, int rounds, int batch);

}  // namespace projtrack::bench
