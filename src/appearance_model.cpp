#include "appearance_model.hpp"

#include <algorithm>
#include <cmath>

namespace projtrack {

void AppearanceModel::reset() {
  object_.assign(kBins, 0.f);
  surroundings_.assign(kBins, 0.f);
  object_total_ = 0;
  lut_.fill(0);
  seen_.fill(0);
}

void AppearanceModel::count(const ColorView& frame, const Mask& m, std::vector<float>& hist) const {
  hist.assign(kBins, 0.f);
  const Rect r = m.rect() & Rect{0, 0, frame.luma.width, frame.luma.height};
  for (int y = r.y; y < r.bottom(); ++y) {
    const std::uint8_t* in = m.row(y - m.rect().y) - m.rect().x;
    const std::uint8_t* luma = frame.luma.row(y);
    for (int x = r.x; x < r.right(); ++x) {
      if (!in[x]) continue;
      const std::uint8_t u = chroma_ ? frame.chroma.u_at(x, y) : 0;
      const std::uint8_t v = chroma_ ? frame.chroma.v_at(x, y) : 0;
      hist[index(luma[x], u, v)] += 1.f;
    }
  }
}

void AppearanceModel::learn(const ColorView& frame, const Mask& object, const Mask& surroundings,
                            double rate) {
  if (object_.size() != kBins) reset();
  rate = std::clamp(rate, 0.0, 1.0);
  if (empty()) {
    rate = 1.0;
    chroma_ = frame.has_chroma();
  }
  const auto blend = [&](const Mask& m, std::vector<float>& hist) {
    count(frame, m, scratch_);
    for (int b = 0; b < kBins; ++b)
      hist[b] = static_cast<float>((1 - rate) * hist[b] + rate * scratch_[b]);
  };
  blend(object, object_);
  blend(surroundings, surroundings_);
  object_total_ = 0;
  for (float c : object_) object_total_ += c;
  rebuild();
}

void AppearanceModel::rebuild() {
  // Lighting moves a colour along luma more than along chroma: counts spread to the next luma
  // bin (by half), never across chroma, so a neutral and a reddish dark stay apart.
  const int step = chroma_ ? 1024 : 1, bins = chroma_ ? kBins : 64;
  const auto smoothed = [&](const std::vector<float>& h, int b) {
    double s = h[b];
    if (b - step >= 0) s += 0.5 * h[b - step];
    if (b + step < bins) s += 0.5 * h[b + step];
    return s;
  };
  // A colour seen a few times, or never, is no evidence of the object: a pseudo-count that
  // grows slowly with the object's size keeps it low.
  const double prior = 2.0 + 1e-4 * object_total_;
  for (int b = 0; b < bins; ++b) {
    const double o = smoothed(object_, b), s = smoothed(surroundings_, b);
    lut_[b] = static_cast<std::uint8_t>(std::lround(255.0 * o / (o + s + prior)));
    seen_[b] = o + s >= 1.0;
  }
}

template <class F>
void AppearanceModel::for_each_bin(const ColorView& frame, const Rect& r, int y, F&& f) const {
  const std::uint8_t* luma = frame.luma.row(y);
  if (!chroma_ || !frame.has_chroma()) {
    for (int x = r.x; x < r.right(); ++x) f(index(luma[x], 128, 128), x);
    return;
  }
  const ChromaView& c = frame.chroma;
  const std::uint8_t* u = c.u + static_cast<std::ptrdiff_t>(y >> c.shift_y) * c.stride;
  const std::uint8_t* v = c.v + static_cast<std::ptrdiff_t>(y >> c.shift_y) * c.stride;
  for (int x = r.x; x < r.right(); ++x) {
    const std::ptrdiff_t k = static_cast<std::ptrdiff_t>(x >> c.shift_x) * c.pixel_stride;
    f(bin(luma[x], u[k], v[k]), x);
  }
}

void AppearanceModel::likelihood(const ColorView& frame, const Rect& roi,
                                 std::vector<std::uint8_t>& out) const {
  const Rect r = roi & Rect{0, 0, frame.luma.width, frame.luma.height};
  out.resize(static_cast<std::size_t>(std::max(0, roi.width)) * std::max(0, roi.height));
  std::fill(out.begin(), out.end(), 0);
  if (empty()) return;
  for (int y = r.y; y < r.bottom(); ++y) {
    std::uint8_t* o = out.data() + static_cast<std::size_t>(y - roi.y) * roi.width - roi.x;
    for_each_bin(frame, r, y, [&](int b, int x) { o[x] = lut_[b]; });
  }
}

void AppearanceModel::seen(const ColorView& frame, const Rect& roi,
                           std::vector<std::uint8_t>& out) const {
  const Rect r = roi & Rect{0, 0, frame.luma.width, frame.luma.height};
  out.resize(static_cast<std::size_t>(std::max(0, roi.width)) * std::max(0, roi.height));
  std::fill(out.begin(), out.end(), 0);
  for (int y = r.y; y < r.bottom(); ++y) {
    std::uint8_t* o = out.data() + static_cast<std::size_t>(y - roi.y) * roi.width - roi.x;
    for_each_bin(frame, r, y, [&](int b, int x) { o[x] = seen_[b]; });
  }
}

}  // namespace projtrack
