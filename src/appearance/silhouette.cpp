#include "appearance/silhouette.hpp"

#include <algorithm>

namespace projtrack {

namespace {

// Each edge-bounded region's sum of likelihoods (sums[0]: the edge pixels'), and whether the
// border of the area cuts it.
void sum_regions(const RegionLabels& regions, const ImageView& like,
                 std::vector<std::uint32_t>& sums, std::vector<std::uint8_t>& cut) {
  const int w = like.width, h = like.height;
  sums.assign(static_cast<std::size_t>(regions.count()) + 1, 0);
  for (int y = 0; y < h; ++y) {
    const std::int32_t* l = regions.row(y);
    const std::uint8_t* lk = like.row(y);
    for (int x = 0; x < w; ++x) sums[l[x]] += lk[x];
  }
  cut.assign(sums.size(), 0);
  for (int x = 0; x < w; ++x) cut[regions.row(0)[x]] = cut[regions.row(h - 1)[x]] = 1;
  for (int y = 0; y < h; ++y) cut[regions.row(y)[0]] = cut[regions.row(y)[w - 1]] = 1;
}

// The object-like pixels near the prior: a small region whole, by its mean likelihood; a region
// cut by the area's border may be far larger than what is seen of it (the wall, the arm), so it
// is decided pixel by pixel, as a large one.
void mark_object_like(const RegionLabels& regions, const std::vector<std::uint32_t>& sums,
                      const std::vector<std::uint8_t>& cut, const ImageView& like, const Mask& near,
                      double small, Mask& out) {
  const int w = like.width, h = like.height;
  for (int y = 0; y < h; ++y) {
    const std::int32_t* l = regions.row(y);
    const std::uint8_t* lk = like.row(y);
    const std::uint8_t* n = near.row(y);
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < w; ++x) {
      if (!l[x] || !n[x]) continue;
      const std::int32_t size = regions.size(l[x]);
      o[x] = size < small && !cut[l[x]] ? sums[l[x]] >= 128u * static_cast<std::uint32_t>(size)
                                        : lk[x] >= 128;
    }
  }
}

// An edge pixel near the prior between two object pixels (across it, either way) belongs to the
// object; `out` is left 0 or 1.
void join_across_edges(const RegionLabels& regions, const Mask& near, Mask& out) {
  const int w = out.rect().width, h = out.rect().height;
  for (int y = 1; y + 1 < h; ++y) {
    const std::int32_t* l = regions.row(y);
    const std::uint8_t *up = out.row(y - 1), *down = out.row(y + 1);
    std::uint8_t* o = out.row(y);
    for (int x = 1; x + 1 < w; ++x)
      if (!l[x] && near.row(y)[x] && ((o[x - 1] & 1 && o[x + 1] & 1) || (up[x] & 1 && down[x] & 1)))
        o[x] = 2;  // marked, so it does not join the next edge pixel in turn
  }
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < w; ++x) o[x] = o[x] != 0;
  }
}

// How many pixels of each component lie on the prior (overlap[0]: of the background).
void overlap_with(const RegionLabels& components, const Mask& prior,
                  std::vector<std::int64_t>& overlap) {
  const int w = components.width(), h = components.height();
  overlap.assign(static_cast<std::size_t>(components.count()) + 1, 0);
  for (int y = 0; y < h; ++y) {
    const std::int32_t* c = components.row(y);
    const std::uint8_t* pr = prior.row(y);
    for (int x = 0; x < w; ++x) overlap[c[x]] += pr[x];
  }
}

// The object's pieces: a finger across it cuts it in two, so every component that lies mostly
// where the object was (or holds the hint) is kept, each big enough to be more than a speck;
// with none, the component that overlaps the prior most, or else the largest.
void choose_pieces(const RegionLabels& components, const std::vector<std::int64_t>& overlap,
                   int hinted, double min_piece_area, bool all_in_reach,
                   std::vector<std::uint8_t>& keep) {
  keep.assign(overlap.size(), 0);
  int best = 0;
  std::int64_t best_score = -1;
  for (int c = 1; c <= components.count(); ++c) {
    const double size = components.size(c);
    keep[c] = c == hinted || ((all_in_reach || 2 * overlap[c] >= size) && size >= min_piece_area);
    const std::int64_t score = overlap[c] * (std::int64_t{1} << 32) + components.size(c);
    if (score > best_score) best_score = score, best = c;
  }
  if (std::find(keep.begin() + 1, keep.end(), 1) == keep.end()) keep[best] = 1;
}

// `out` set where the component is kept, clear elsewhere.
void keep_only(const RegionLabels& components, const std::vector<std::uint8_t>& keep, Mask& out) {
  const int w = components.width(), h = components.height();
  for (int y = 0; y < h; ++y) {
    const std::int32_t* c = components.row(y);
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < w; ++x) o[x] = keep[c[x]];
  }
}

}  // namespace

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
  const ImageView area_edges(edges.row(a.y - roi.y) + (a.x - roi.x), a.width, a.height,
                             edges.stride);
  const ImageView like(
      likelihood.data() + static_cast<std::size_t>(a.y - roi.y) * roi.width + (a.x - roi.x),
      a.width, a.height, roi.width);

  // Where the object may be: the prior, grown by the reach.
  embed(prior, a, prior_);
  ops_.dilate(prior_, p.reach, near_);
  // Edge-bounded regions taken whole or pixel by pixel, and the edges between them.
  regions_.label(area_edges, true);
  sum_regions(regions_, like, sums_, cut_);
  mark_object_like(regions_, sums_, cut_, like, near_, p.small_region * expected_area, out);
  join_across_edges(regions_, near_, out);
  // Its pieces, and no holes: a projection has none.
  components_.label(out.view(), false);
  if (components_.count() == 0) return false;
  overlap_with(components_, prior_, overlap_);
  const int hinted = a.contains(hint) ? components_.row(hint.y - a.y)[hint.x - a.x] : 0;
  choose_pieces(components_, overlap_, hinted, p.min_piece * expected_area, p.all_pieces_in_reach,
                keep_);
  keep_only(components_, keep_, out);
  ops_.fill_holes(out);
  out.crop();
  return !out.empty();
}

}  // namespace projtrack
