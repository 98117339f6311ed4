#include "object_finder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace projtrack {

namespace {

int colour_bin(const ColorView& f, int x, int y) {
  const std::uint8_t luma = f.luma.row(y)[x];
  if (!f.has_chroma()) return luma >> 2;
  return AppearanceModel::bin(luma, f.chroma.u_at(x, y), f.chroma.v_at(x, y));
}

struct RegionStats {
  std::int64_t size = 0;
  Rect box;
  std::int64_t moving = 0;
};

}  // namespace

void ObjectFinder::foreground(const ColorView& frame, const FinderParams& p) {
  const int w = frame.luma.width, h = frame.luma.height;
  const int strip = std::max(4, static_cast<int>(std::lround(p.border * std::min(w, h))));
  border_counts_.assign(AppearanceModel::kBins, 0);
  std::int64_t strip_pixels = 0;
  for (int y = 0; y < h; ++y) {
    const bool whole_row = y < strip || y >= h - strip;
    for (int x = 0; x < w; ++x) {
      if (!whole_row && x == strip) x = std::max(strip, w - strip);  // skip the middle
      if (x >= w) break;
      ++border_counts_[colour_bin(frame, x, y)];
      ++strip_pixels;
    }
  }
  const double seen = std::max(8.0, p.border_share * static_cast<double>(strip_pixels));
  background_.resize(AppearanceModel::kBins);
  for (int b = 0; b < AppearanceModel::kBins; ++b) background_[b] = border_counts_[b] >= seen;
  candidates_.reset({0, 0, w, h});
  for (int y = 0; y < h; ++y) {
    std::uint8_t* c = candidates_.row(y);
    for (int x = 0; x < w; ++x) c[x] = !background_[colour_bin(frame, x, y)];
  }
  // An opening drops specks and one-pixel bridges between regions.
  ops_.erode(candidates_, 1, opened_);
  ops_.dilate(opened_, 1, candidates_);
}

template <class Score>
int ObjectFinder::best_region(Score&& score) {
  regions_.label(candidates_.view(), false);
  std::vector<RegionStats> stats(static_cast<std::size_t>(regions_.count()) + 1);
  std::vector<BoundsAccumulator> bounds(stats.size());
  for (int y = 0; y < regions_.height(); ++y) {
    const std::int32_t* l = regions_.row(y);
    for (int x = 0; x < regions_.width(); ++x) {
      if (!l[x]) continue;
      ++stats[l[x]].size;
      bounds[l[x]].add(x, y);
    }
  }
  for (std::size_t i = 1; i < stats.size(); ++i) stats[i].box = bounds[i].rect();
  int best = 0;
  double best_score = -1;
  for (int l = 1; l <= regions_.count(); ++l) {
    const double s = score(l, stats[l]);
    if (s > best_score) best_score = s, best = l;
  }
  return best_score >= 0 ? best : 0;
}

void ObjectFinder::copy_region(int label, Mask& out) {
  BoundsAccumulator bounds;
  for (int y = 0; y < regions_.height(); ++y) {
    const std::int32_t* l = regions_.row(y);
    for (int x = 0; x < regions_.width(); ++x)
      if (l[x] == label) bounds.add(x, y);
  }
  const Rect r = bounds.rect();
  out.reset(r);
  for (int y = r.y; y < r.bottom(); ++y) {
    const std::int32_t* l = regions_.row(y);
    std::uint8_t* o = out.row(y - r.y);
    for (int x = r.x; x < r.right(); ++x) o[x - r.x] = l[x] == label;
  }
  ops_.fill_holes(out);
}

bool ObjectFinder::from_seed(const ColorView& frame, Point2i seed, const FinderParams& p, Mask& out,
                             std::string& why) {
  foreground(frame, p);
  const int w = frame.luma.width, h = frame.luma.height;
  // The seed's own pixel, or the nearest candidate pixel within a twentieth of the frame.
  const int reach = std::max(8, std::min(w, h) / 20);
  std::optional<Point2i> start;
  for (int r = 0; r <= reach && !start; ++r) {
    for (int dy = -r; dy <= r && !start; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
        const Point2i q{seed.x + dx, seed.y + dy};
        if (candidates_.at(q)) {
          start = q;
          break;
        }
      }
    }
  }
  if (!start) {
    why = "no colour near the inner point that the frame's border does not show too";
    return false;
  }
  regions_.label(candidates_.view(), false);
  copy_region(regions_.row(start->y)[start->x], out);
  const double area = moments(out).area, frame_area = static_cast<double>(w) * h;
  if (area > p.max_area * frame_area) {
    why = "the region around the inner point covers most of the frame";
    return false;
  }
  return true;
}

bool ObjectFinder::from_motion(const ColorView& frame, const MotionDetector::Motion& motion,
                               const FinderParams& p, Mask& out, Point2i& seed, std::string& why) {
  foreground(frame, p);
  const int w = frame.luma.width, h = frame.luma.height;
  const double frame_area = static_cast<double>(w) * h;
  regions_.label(candidates_.view(), false);
  moving_.assign(static_cast<std::size_t>(regions_.count()) + 1, 0);
  for (const Point2i& q : motion.points) moving_[regions_.row(q.y)[q.x]] += 1;
  const double per_sample = static_cast<double>(std::max(1, motion.step)) * motion.step;
  const int label = best_region([&](int l, const RegionStats& s) {
    const Rect& b = s.box;
    const double share = moving_[l] * per_sample / static_cast<double>(s.size);
    if (s.size < p.min_area * frame_area || s.size > p.max_area * frame_area) return -1.0;
    if (b.x == 0 || b.y == 0 || b.right() == w || b.bottom() == h) return -1.0;
    if (share < p.min_moving) return -1.0;
    return share * static_cast<double>(s.size) / (static_cast<double>(b.width) * b.height);
  });
  if (!label) {
    why = "no moving region of its own colours, wholly in view";
    return false;
  }
  copy_region(label, out);
  seed = ops_.deepest(out).first;
  return true;
}

bool ObjectFinder::from_model(const ColorView& frame, const AppearanceModel& model,
                              const MotionDetector::Motion& motion, double area, double factor,
                              Point2d near, const FinderParams& p, Mask& out, Point2i& seed,
                              std::string& why) {
  const int w = frame.luma.width, h = frame.luma.height;
  model.likelihood(frame, {0, 0, w, h}, like_);
  candidates_.reset({0, 0, w, h});
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* l = like_.data() + static_cast<std::size_t>(y) * w;
    std::uint8_t* c = candidates_.row(y);
    for (int x = 0; x < w; ++x) c[x] = l[x] >= 128;
  }
  ops_.erode(candidates_, 1, opened_);
  ops_.dilate(opened_, 1, candidates_);
  regions_.label(candidates_.view(), false);
  moving_.assign(static_cast<std::size_t>(regions_.count()) + 1, 0);
  for (const Point2i& q : motion.points) moving_[regions_.row(q.y)[q.x]] += 1;
  const double per_sample = static_cast<double>(std::max(1, motion.step)) * motion.step;
  const double diagonal = std::hypot(w, h);
  const int label = best_region([&](int l, const RegionStats& s) {
    const double size = static_cast<double>(s.size);
    if (size < area / factor || size > area * factor) return -1.0;
    if (moving_[l] * per_sample / size < p.min_moving) return -1.0;
    const Point2d c{s.box.x + s.box.width / 2.0, s.box.y + s.box.height / 2.0};
    return 1.0 - distance(c, near) / diagonal;  // nearest first
  });
  if (!label) {
    why = "nothing of the object's colours and size moves";
    return false;
  }
  copy_region(label, out);
  seed = ops_.deepest(out).first;
  return true;
}

}  // namespace projtrack
