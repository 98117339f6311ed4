// Adversarial content: frames made to cost the estimators and the tracker as much work as
// possible (issue 16), shared by the tests (tests/tracker/test_work_budget.cpp) and the speed
// benchmark (bench/speed/main.cpp). Every frame is fresh: the same kind gives another pattern on
// every index.
#pragma once

#include <iterator>
#include <opencv2/core.hpp>

namespace projtrack::synthetic {

enum class Adversary {
  Noise,     // every pixel a uniformly random grey level
  Dots5,     // white 1-px dots on black, 5 % of the pixels, fresh on every frame
  Dots15,    // ... 15 % (the 200–330 ms pixel-filling frames at 1080p)
  Dots40,    // ... 40 %
  Blocks4,   // random black or white 4×4 blocks
  Checker1,  // a 1-px checkerboard, inverted on every other frame
  Checker8,  // an 8-px checkerboard, inverted on every other frame
  Comb,      // 1-px teeth 1 px apart joined by a spine: one long corridor, rays short across it
  Maze,      // a random maze, corridors 2 px wide between 1-px walls: fills follow every corridor
  Spiral,    // a square spiral, a 2-px corridor between 1-px walls, from the centre out
};

struct AdversaryInfo {
  Adversary kind;
  const char* name;  // lower-case, for test names, CSV rows and the report
};

inline constexpr AdversaryInfo kAdversaries[] = {
    {Adversary::Noise, "noise"},        {Adversary::Dots5, "dots-5"},
    {Adversary::Dots15, "dots-15"},     {Adversary::Dots40, "dots-40"},
    {Adversary::Blocks4, "blocks-4"},   {Adversary::Checker1, "checker-1"},
    {Adversary::Checker8, "checker-8"}, {Adversary::Comb, "comb"},
    {Adversary::Maze, "maze"},          {Adversary::Spiral, "spiral"},
};
inline constexpr int kAdversaryCount = static_cast<int>(std::size(kAdversaries));

// Frame `index` of the sequence of `kind`, width × height, CV_8U: 0 and 255 (grey levels for
// Noise). As a frame it is luma; as an edge map, non-zero is an edge. The same arguments give the
// same frame.
cv::Mat adversarial_frame(Adversary kind, int width, int height, int index);

}  // namespace projtrack::synthetic
