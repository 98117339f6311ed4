#include "appearance/silhouette.hpp"

#include <algorithm>

namespace projtrack {

bool SilhouetteSegmenter::segment(const std::vector<std::uint8_t>& likelihood,
                                  const ImageView& edges, const Rect& roi, const Mask& prior,
                                  double expected_area, Point2i hint, const SilhouetteParams& p,
                                  Mask& out) {
  if (roi.empty() || edges.width != roi.width || edges.height != roi.height ||
      likelihood.size() < static_cast<std::size_t>(roi.width) * roi.height) {
    out.reset({});
    return false;
  }
  // Only within reach of the prior can the object be: the work is done there alone.
  const Rect a = Rect{prior.rect().x - p.reach, prior.rect().y - p.reach,
                      prior.rect().width + 2 * p.reach, prior.rect().height + 2 * p.reach} &
                 roi;
  out.reset(a);
  if (a.empty()) return false;
  const int w = a.width, h = a.height;
  const ImageView area_edges(edges.row(a.y - roi.y) + (a.x - roi.x), w, h, edges.stride);
  const auto like_row = [&](int y) {
    return likelihood.data() + static_cast<std::size_t>(y + a.y - roi.y) * roi.width +
           (a.x - roi.x);
  };

  // Where the object may be: the prior, grown by the reach.
  prior_.reset(a);
  const Rect common = prior.rect() & a;
  for (int y = common.y; y < common.bottom(); ++y)
    std::copy_n(prior.row(y - prior.rect().y) + (common.x - prior.rect().x), common.width,
                prior_.row(y - a.y) + (common.x - a.x));
  ops_.dilate(prior_, p.reach, near_);

  // Each edge-bounded region's mean likelihood.
  regions_.label(area_edges, true);
  sums_.assign(static_cast<std::size_t>(regions_.count()) + 1, 0);
  for (int y = 0; y < h; ++y) {
    const std::int32_t* l = regions_.row(y);
    const std::uint8_t* like = like_row(y);
    for (int x = 0; x < w; ++x) sums_[l[x]] += like[x];
  }
  // A region cut by the work area's border may be far larger than what is seen of it (the wall,
  // the arm): it is decided pixel by pixel, as a large one.
  cut_.assign(sums_.size(), 0);
  for (int x = 0; x < w; ++x) cut_[regions_.row(0)[x]] = cut_[regions_.row(h - 1)[x]] = 1;
  for (int y = 0; y < h; ++y) cut_[regions_.row(y)[0]] = cut_[regions_.row(y)[w - 1]] = 1;
  const double small = p.small_region * expected_area;
  for (int y = 0; y < h; ++y) {
    const std::int32_t* l = regions_.row(y);
    const std::uint8_t* like = like_row(y);
    const std::uint8_t* n = near_.row(y);
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < w; ++x) {
      if (!l[x] || !n[x]) continue;
      const std::int32_t size = regions_.size(l[x]);
      o[x] = size < small && !cut_[l[x]] ? sums_[l[x]] >= 128u * static_cast<std::uint32_t>(size)
                                         : like[x] >= 128;
    }
  }
  // An edge pixel between two object pixels (across it, either way) belongs to the object.
  for (int y = 1; y + 1 < h; ++y) {
    const std::int32_t* l = regions_.row(y);
    const std::uint8_t *up = out.row(y - 1), *down = out.row(y + 1);
    std::uint8_t* o = out.row(y);
    for (int x = 1; x + 1 < w; ++x)
      if (!l[x] && near_.row(y)[x] &&
          ((o[x - 1] & 1 && o[x + 1] & 1) || (up[x] & 1 && down[x] & 1)))
        o[x] = 2;  // marked, so it does not join the next edge pixel in turn
  }
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < w; ++x) o[x] = o[x] != 0;
  }

  // The object's pieces: a finger across it cuts it in two, so every component that lies mostly
  // where the object was (or holds the hint) is kept, each big enough to be more than a speck;
  // with none, the component that overlaps the prior most, or else the largest.
  components_.label(out.view(), false);
  if (components_.count() == 0) return false;
  overlap_.assign(static_cast<std::size_t>(components_.count()) + 1, 0);
  for (int y = 0; y < h; ++y) {
    const std::int32_t* c = components_.row(y);
    const std::uint8_t* pr = prior_.row(y);
    for (int x = 0; x < w; ++x) overlap_[c[x]] += pr[x];
  }
  const int hinted = a.contains(hint) ? components_.row(hint.y - a.y)[hint.x - a.x] : 0;
  keep_.assign(overlap_.size(), 0);
  int best = 0;
  std::int64_t best_score = -1;
  for (int c = 1; c <= components_.count(); ++c) {
    const double size = components_.size(c);
    keep_[c] = c == hinted || ((p.all_pieces_in_reach || 2 * overlap_[c] >= size) &&
                               size >= p.min_piece * expected_area);
    const std::int64_t score = overlap_[c] * (std::int64_t{1} << 32) + components_.size(c);
    if (score > best_score) best_score = score, best = c;
  }
  if (std::find(keep_.begin() + 1, keep_.end(), 1) == keep_.end()) keep_[best] = 1;
  for (int y = 0; y < h; ++y) {
    const std::int32_t* c = components_.row(y);
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < w; ++x) o[x] = keep_[c[x]];
  }
  ops_.fill_holes(out);
  out.crop();
  return !out.empty();
}

}  // namespace projtrack
