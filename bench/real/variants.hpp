// The lighting and noise variants: the clip as footage we never tuned on would show it. The
// geometric variants (edge, half, mirror) and the fast one (every third frame) are the plan's
// crop, scale, mirror and step (prepare.py, which moves the truth alike).
//   dark    a dimmer scene: luma at kDarkLuma of its range above black, chroma at kDarkChroma
//           of its swing
//   dim     a dim room: the light at kDimLight (luma and chroma's distance from neutral × it)
//   bright  overexposed: luma × kBrightGain + kBrightOffset, the highlights burnt out at 255
//   gamma   shadows lifted: luma through a gamma of kGamma (255 · (Y / 255)^kGamma)
//   warm    a warm light: luma × kWarmLuma, Cb shifted by kWarmCb, Cr by kWarmCr
//   noise   sensor noise: Gaussian, σ kNoiseLuma grey levels on luma, kNoiseChroma on chroma
//           (fixed seed)
// Their settings are written to meta.json (write_variant_settings), from which the report
// describes them.
#pragma once

#include <opencv2/core.hpp>
#include <ostream>
#include <string>

#include "clip.hpp"

namespace projtrack::bench {

constexpr double kDarkLuma = 0.55, kDarkChroma = 0.8;
constexpr double kDimLight = 0.4;
constexpr double kWarmLuma = 0.92, kWarmCb = -10, kWarmCr = 12;
constexpr double kBrightGain = 1.35, kBrightOffset = -20;
constexpr double kGamma = 0.5;
constexpr double kNoiseLuma = 8, kNoiseChroma = 4;
constexpr int kFastStep = 3;  // prepare.py's FAST_STEP

// One lighting variant applied frame after frame (the noise from one generator per clip).
class Lighting {
 public:
  explicit Lighting(std::string how) : how_(std::move(how)), rng_(12345) {}
  void apply(I420Frame& f);

 private:
  std::string how_;
  cv::RNG rng_;
};

// The variants' settings as a JSON object's members.
void write_variant_settings(std::ostream& meta);

}  // namespace projtrack::bench
