#include "segmentation/grab_cut.hpp"

#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {
constexpr std::uint64_t kSeed = 0x5eed;  // any fixed state: the answer need only be repeatable
}

bool repeatable_grab_cut(const cv::Mat& bgr, cv::Mat& labels, const cv::Rect& box, int rounds,
                         int mode) {
  cv::RNG& rng = cv::theRNG();
  const std::uint64_t callers = rng.state;
  rng.state = kSeed;
  cv::Mat bgd, fgd;
  bool cut = true;
  try {
    cv::grabCut(bgr, labels, box, bgd, fgd, rounds, mode);
  } catch (const cv::Exception&) {
    cut = false;
  }
  rng.state = callers;
  return cut;
}

}  // namespace projtrack
