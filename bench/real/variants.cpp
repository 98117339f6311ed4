#include "variants.hpp"

#include <cmath>
#include <opencv2/core.hpp>

namespace projtrack::bench {

void Lighting::apply(I420Frame& f) {
  if (how_ == "dark") {
    f.y.convertTo(f.y, -1, kDarkLuma, 16 * (1 - kDarkLuma));
    f.u.convertTo(f.u, -1, kDarkChroma, 128 * (1 - kDarkChroma));
    f.v.convertTo(f.v, -1, kDarkChroma, 128 * (1 - kDarkChroma));
  } else if (how_ == "dim") {
    f.y.convertTo(f.y, -1, kDimLight, 0);
    f.u.convertTo(f.u, -1, kDimLight, 128 * (1 - kDimLight));
    f.v.convertTo(f.v, -1, kDimLight, 128 * (1 - kDimLight));
  } else if (how_ == "bright") {
    f.y.convertTo(f.y, -1, kBrightGain, kBrightOffset);  // saturates at 0 and 255
  } else if (how_ == "gamma") {
    cv::Mat lut(1, 256, CV_8U);
    for (int v = 0; v < 256; ++v)
      lut.at<std::uint8_t>(v) = cv::saturate_cast<std::uint8_t>(255 * std::pow(v / 255.0, kGamma));
    cv::LUT(f.y, lut, f.y);
  } else if (how_ == "warm") {
    f.y.convertTo(f.y, -1, kWarmLuma, 0);
    f.u.convertTo(f.u, -1, 1, kWarmCb);
    f.v.convertTo(f.v, -1, 1, kWarmCr);
  } else if (how_ == "noise") {
    for (auto [m, sigma] :
         {std::pair{&f.y, kNoiseLuma}, {&f.u, kNoiseChroma}, {&f.v, kNoiseChroma}}) {
      cv::Mat n(m->size(), CV_16SC1), wide;
      rng_.fill(n, cv::RNG::NORMAL, 0, sigma);
      m->convertTo(wide, CV_16SC1);
      wide += n;
      wide.convertTo(*m, CV_8UC1);
    }
  }
}

void write_variant_settings(std::ostream& meta) {
  meta << "\"mirror\": {}, \"edge\": {}, \"half\": {}, \"dark\": {\"luma\": " << kDarkLuma
       << ", \"chroma\": " << kDarkChroma << "}, \"dim\": {\"light\": " << kDimLight
       << "}, \"bright\": {\"gain\": " << kBrightGain << ", \"offset\": " << kBrightOffset
       << "}, \"gamma\": {\"gamma\": " << kGamma << "}, \"warm\": {\"luma\": " << kWarmLuma
       << ", \"cb\": " << kWarmCb << ", \"cr\": " << kWarmCr
       << "}, \"noise\": {\"luma_sigma\": " << kNoiseLuma << ", \"chroma_sigma\": " << kNoiseChroma
       << "}, \"fast\": {\"step\": " << kFastStep << "}";
}

}  // namespace projtrack::bench
