#include "segmentation/grab_cut.hpp"

#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

constexpr std::uint64_t kSeed = 0x9e3779b97f4a7c15;  // any fixed value: the cut must not vary

// Sets the thread's generator to a fixed seed, and gives it back its state at the end of scope.
class FixedRandom {
 public:
  FixedRandom() : saved_(cv::theRNG()) { cv::theRNG() = cv::RNG(kSeed); }
  ~FixedRandom() { cv::theRNG() = saved_; }
  FixedRandom(const FixedRandom&) = delete;
  FixedRandom& operator=(const FixedRandom&) = delete;

 private:
  cv::RNG saved_;
};

}  // namespace

bool grab_cut(const cv::Mat& bgr, cv::Mat& labels, const cv::Rect& rect, int rounds) {
  const FixedRandom fixed;
  cv::Mat bgd, fgd;
  try {
    cv::grabCut(bgr, labels, rect, bgd, fgd, rounds,
                rect.empty() ? cv::GC_INIT_WITH_MASK : cv::GC_INIT_WITH_RECT);
  } catch (const cv::Exception&) {
    return false;
  }
  return true;
}

}  // namespace projtrack
