// One routine written by hand against the library call that does the same job, side by side in
// one run: the time per call (median over rounds, the two alternating) and the heap allocations
// per call in steady state (after warm-up, as a stream calls them frame after frame).
#pragma once

#include <cstdio>
#include <functional>
#include <string>

namespace projtrack::handwritten {

struct Cost {
  double us = 0;      // per call, median over rounds
  double allocs = 0;  // heap allocations per call, after warm-up
};

struct Duel {
  Cost ours, library;
};

// Each side is warmed up (its buffers sized), then timed in `rounds` rounds of `calls` calls,
// which side goes first alternating from round to round, so a noisy machine slows both alike.
Duel duel(const std::function<void()>& ours, const std::function<void()>& library, int rounds,
          int calls);

// handwritten.csv: one row per routine and input.
struct Row {
  std::string routine;  // what it does
  std::string where;    // our file (and function)
  std::string library;  // the library call(s) measured against it
  std::string input;    // what both were given
  std::string same;  // whether the outputs are identical: "yes", "no (why)", or "" (not compared)
};

void write_header(std::FILE* out);
void write_row(std::FILE* out, const Row& r, const Duel& d);
// A routine whose own time could not be taken alone (its reason in `why`): the library's alone.
void write_library_only(std::FILE* out, const Row& r, const Cost& library, const std::string& why);

// Rounds and calls per round of every duel (fewer with --quick).
struct Effort {
  int rounds = 15, calls = 20;
};

}  // namespace projtrack::handwritten
