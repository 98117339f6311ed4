// The object's colours against its surroundings': a per-pixel object likelihood, learned from the
// silhouette and a ring around it, as colour-based model-free trackers do (Possegger et al., "In
// Defense of Color-based Model-free Tracking", CVPR 2015).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mask.hpp"
#include "projtrack/color_view.hpp"
#include "projtrack/geometry.hpp"

namespace projtrack {

class AppearanceModel {
 public:
  // Colour bins: 16 of luma (16 levels each) × 32 of Cr × 32 of Cb (8 levels each), so that a
  // dark neutral object and a dark reddish hand fall apart; gray frames use 64 bins of luma alone.
  static constexpr int kBins = 16 * 32 * 32;
  // Added to (xor'ed with) a colour bin, the bin of the same chroma one luma step away.
  static constexpr int kLumaStep = 1 << 10;

  static int bin(std::uint8_t y, std::uint8_t u, std::uint8_t v) {
    return ((y >> 4) << 10) | ((v >> 3) << 5) | (u >> 3);
  }

  // Forgets everything.
  void reset();
  bool empty() const { return object_total_ <= 0; }

  // In every call, pixel (x, y) of the masks and rectangles is pixel (x - origin.x, y - origin.y)
  // of `image` (a work frame: see WorkFrame); what falls outside `image` is ignored.

  // Counts the colours of `object` (its set pixels) and of `surroundings`, and blends them into
  // the model: rate 1 replaces what it knew, a small rate adapts it slowly.
  void learn(const ColorView& image, Point2i origin, const Mask& object, const Mask& surroundings,
             double rate);

  // The same with the surroundings given as counts per colour bin (the colours of the frame's
  // border, say), weighed as many pixels as the object has.
  void learn(const ColorView& image, Point2i origin, const Mask& object,
             const std::vector<std::uint32_t>& surroundings);

  // P(object | colour) of every pixel of `roi`, scaled to 0–255, into `out` (roi.width ×
  // roi.height, row stride roi.width): a colour seen mostly on the object scores high, one seen
  // mostly around it or never seen scores low.
  void likelihood(const ColorView& image, Point2i origin, const Rect& roi,
                  std::vector<std::uint8_t>& out) const;
  // 1 for every pixel of `roi` whose colour the model has seen more around the object than on
  // it, 0 for the others (the object's colours and those it knows nothing of); same layout as
  // likelihood().
  void surroundings_like(const ColorView& image, Point2i origin, const Rect& roi,
                         std::vector<std::uint8_t>& out) const;
  // The same for one colour.
  std::uint8_t likelihood(std::uint8_t y, std::uint8_t u, std::uint8_t v) const {
    return lut_[index(y, u, v)];
  }

 private:
  int index(std::uint8_t y, std::uint8_t u, std::uint8_t v) const {
    return chroma_ ? bin(y, u, v) : y >> 2;
  }
  void count(const ColorView& image, Point2i origin, const Mask& m, std::vector<float>& hist) const;
  void rebuild();
  // Calls f(bin, x) for x in [x0, x1) of row y of `image`.
  template <class F>
  void for_each_bin(const ColorView& image, int y, int x0, int x1, F&& f) const;
  // Calls f(bin, out index) for every pixel of `roi` inside `image`.
  template <class F>
  void over_roi(const ColorView& image, Point2i origin, const Rect& roi, F&& f) const;

  bool chroma_ = true;
  std::vector<float> object_, surroundings_, scratch_;  // counts per bin
  double object_total_ = 0;
  std::array<std::uint8_t, kBins> lut_{}, around_{};
};

}  // namespace projtrack
