#include "appearance/appearance_model.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

void AppearanceModel::reset() {
  object_.assign(kBins, 0.f);
  surroundings_.assign(kBins, 0.f);
  object_total_ = 0;
  lut_.fill(0);
  around_.fill(0);
}

void AppearanceModel::count(const ColorView& image, Point2i origin, const Mask& m,
                            std::vector<float>& hist) const {
  hist.assign(kBins, 0.f);
  const Rect r =
      Rect{m.rect().x - origin.x, m.rect().y - origin.y, m.rect().width, m.rect().height} &
      Rect{0, 0, image.luma.width, image.luma.height};
  for (int y = r.y; y < r.bottom(); ++y) {
    const std::uint8_t* in = m.row(y + origin.y - m.rect().y) + (origin.x - m.rect().x);
    for_each_bin(image, y, r.x, r.right(), [&](int b, int x) {
      if (in[x]) hist[b] += 1.f;
    });
  }
}

void AppearanceModel::learn(const ColorView& image, Point2i origin, const Mask& object,
                            const Mask& surroundings, double rate) {
  if (object_.size() != kBins) reset();
  rate = std::clamp(rate, 0.0, 1.0);
  if (empty()) {
    rate = 1.0;
    chroma_ = image.has_chroma();
  }
  const auto blend = [&](const Mask& m, std::vector<float>& hist) {
    count(image, origin, m, scratch_);
    for (int b = 0; b < kBins; ++b)
      hist[b] = static_cast<float>((1 - rate) * hist[b] + rate * scratch_[b]);
  };
  blend(object, object_);
  blend(surroundings, surroundings_);
  object_total_ = 0;
  for (float c : object_) object_total_ += c;
  rebuild();
}

void AppearanceModel::learn(const ColorView& image, Point2i origin, const Mask& object,
                            const std::vector<std::uint32_t>& surroundings) {
  reset();
  chroma_ = image.has_chroma();
  count(image, origin, object, object_);
  double objects = 0, around = 0;
  for (float c : object_) objects += c;
  for (std::uint32_t c : surroundings) around += c;
  const double weight = around > 0 ? objects / around : 0;
  for (std::size_t b = 0; b < surroundings.size() && b < surroundings_.size(); ++b)
    surroundings_[b] = static_cast<float>(weight * surroundings[b]);
  object_total_ = objects;
  rebuild();
}

namespace {

constexpr double kEvidencePixels = 1000;

}  // namespace

void AppearanceModel::rebuild() {
  // Lighting moves a colour along luma more than along chroma: counts spread to the next luma
  // bin (by half), never across chroma, so a neutral and a reddish dark stay apart.
  const int step = chroma_ ? kLumaStep : 1, bins = chroma_ ? kBins : 64;
  const auto smoothed = [&](const std::vector<float>& h, int b) {
    double s = h[b];
    if (b - step >= 0) s += 0.5 * h[b - step];
    if (b + step < bins) s += 0.5 * h[b + step];
    return s;
  };
  // A colour seen a few times, or never, is no evidence of the object: a pseudo-count that
  // grows slowly with the object's size keeps it low. "A few" is relative to the object: a small
  // one (under kEvidencePixels, whole pixels: the work scale makes larger ones about 6 000) shows
  // each of its colours only once or twice.
  const double prior = 2.0 * std::min(1.0, object_total_ / kEvidencePixels) + 1e-4 * object_total_;
  for (int b = 0; b < bins; ++b) {
    const double o = smoothed(object_, b), s = smoothed(surroundings_, b);
    lut_[b] = static_cast<std::uint8_t>(std::lround(255.0 * o / (o + s + prior)));
    around_[b] = s > o + 1.0;
  }
}

template <class F>
void AppearanceModel::for_each_bin(const ColorView& image, int y, int x0, int x1, F&& f) const {
  const std::uint8_t* luma = image.luma.row(y);
  if (!chroma_ || !image.has_chroma()) {
    for (int x = x0; x < x1; ++x) f(index(luma[x], 128, 128), x);
    return;
  }
  const ChromaView& c = image.chroma;
  const std::uint8_t* u = c.u + static_cast<std::ptrdiff_t>(y >> c.shift_y) * c.stride;
  const std::uint8_t* v = c.v + static_cast<std::ptrdiff_t>(y >> c.shift_y) * c.stride;
  for (int x = x0; x < x1; ++x) {
    const std::ptrdiff_t k = static_cast<std::ptrdiff_t>(x >> c.shift_x) * c.pixel_stride;
    f(bin(luma[x], u[k], v[k]), x);
  }
}

template <class F>
void AppearanceModel::over_roi(const ColorView& image, Point2i origin, const Rect& roi,
                               F&& f) const {
  const Rect r = Rect{roi.x - origin.x, roi.y - origin.y, roi.width, roi.height} &
                 Rect{0, 0, image.luma.width, image.luma.height};
  for (int y = r.y; y < r.bottom(); ++y) {
    const std::size_t row = static_cast<std::size_t>(y + origin.y - roi.y) * roi.width;
    const int dx = origin.x - roi.x;
    for_each_bin(image, y, r.x, r.right(), [&](int b, int x) { f(b, row + x + dx); });
  }
}

void AppearanceModel::likelihood(const ColorView& image, Point2i origin, const Rect& roi,
                                 std::vector<std::uint8_t>& out) const {
  out.assign(static_cast<std::size_t>(std::max(0, roi.width)) * std::max(0, roi.height), 0);
  if (empty()) return;
  over_roi(image, origin, roi, [&](int b, std::size_t i) { out[i] = lut_[b]; });
}

void AppearanceModel::surroundings_like(const ColorView& image, Point2i origin, const Rect& roi,
                                        std::vector<std::uint8_t>& out) const {
  out.assign(static_cast<std::size_t>(std::max(0, roi.width)) * std::max(0, roi.height), 0);
  over_roi(image, origin, roi, [&](int b, std::size_t i) { out[i] = around_[b]; });
}

}  // namespace projtrack
