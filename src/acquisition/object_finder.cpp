#include "acquisition/object_finder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace projtrack {

namespace {

int colour_bin(const ColorView& f, int x, int y) {
  const std::uint8_t luma = f.luma.row(y)[x];
  if (!f.has_chroma()) return luma >> 2;
  return AppearanceModel::bin(luma, f.chroma.u_at(x, y), f.chroma.v_at(x, y));
}

// A work pixel's centre in the frame.
Point2i to_frame_pixel(Point2i p, int scale) {
  return {p.x * scale + scale / 2, p.y * scale + scale / 2};
}

}  // namespace

void ObjectFinder::load(const ColorView& frame, const FinderParams& p, WorkFrame& work) {
  const int w = frame.luma.width, h = frame.luma.height;
  const int s = work_scale(static_cast<double>(w) * h, p.work_pixels);
  work.build(frame, s, {0, 0, (w + s - 1) / s, (h + s - 1) / s});
}

void ObjectFinder::foreground(const FinderParams& p) {
  const ColorView& f = work_.view();
  const int w = f.luma.width, h = f.luma.height;
  const int strip = std::max(2, static_cast<int>(std::lround(p.border * std::min(w, h))));
  border_counts_.assign(AppearanceModel::kBins, 0);
  std::int64_t strip_pixels = 0;
  for (int y = 0; y < h; ++y) {
    const bool whole_row = y < strip || y >= h - strip;
    for (int x = 0; x < w; ++x) {
      if (!whole_row && x == strip) x = std::max(strip, w - strip);  // skip the middle
      if (x >= w) break;
      ++border_counts_[colour_bin(f, x, y)];
      ++strip_pixels;
    }
  }
  const double seen = std::max(3.0, p.border_share * static_cast<double>(strip_pixels));
  // Seen on the border in luma steps of 32, a bin with its partner: lighting varies a scene's
  // colours along luma more than the object model's fine bins, which tell a dimly lit object
  // from the hand, and a colour of the wall seen a shade lighter is still the wall's.
  const int partner = f.has_chroma() ? AppearanceModel::kLumaStep : 0;
  background_.resize(AppearanceModel::kBins);
  for (int b = 0; b < AppearanceModel::kBins; ++b)
    background_[b] = border_counts_[b] + (partner ? border_counts_[b ^ partner] : 0) >= seen;
  candidates_.reset({0, 0, w, h});
  for (int y = 0; y < h; ++y) {
    std::uint8_t* c = candidates_.row(y);
    for (int x = 0; x < w; ++x) c[x] = !background_[colour_bin(f, x, y)];
  }
  // An opening drops specks and one-pixel bridges between regions.
  ops_.erode(candidates_, 1, opened_);
  ops_.dilate(opened_, 1, candidates_);
}

void ObjectFinder::count_motion(const MotionDetector::Motion& motion, const Rect& area,
                                MotionCounts& out) {
  out.inside.assign(static_cast<std::size_t>(regions_.count()) + 1, 0);
  out.near.assign(out.inside.size(), 0);
  const int s = work_.scale(), w = regions_.width(), h = regions_.height();
  out.per_sample = static_cast<double>(motion.step) * motion.step / (static_cast<double>(s) * s);
  const Rect a = area & Rect{0, 0, w, h};
  if (a.empty()) return;
  samples_.assign(static_cast<std::size_t>(a.width) * a.height, 0);
  // The samples come in row order: those above the area are passed over by a binary search, the
  // work row is found once per frame row and the work column by a table (no division per sample).
  const int x0 = a.x * s, x1 = a.right() * s, y0 = a.y * s, y1 = a.bottom() * s;
  work_column_.resize(static_cast<std::size_t>(x1 - x0));
  for (int x = x0; x < x1; ++x) work_column_[x - x0] = x / s - a.x;
  auto q = std::lower_bound(motion.points.begin(), motion.points.end(), y0,
                            [](const Point2i& p, int y) { return p.y < y; });
  int row_y = -1;
  std::int32_t* row = nullptr;
  for (; q != motion.points.end() && q->y < y1; ++q) {
    if (q->y != row_y) {
      row_y = q->y;
      row = samples_.data() + static_cast<std::size_t>(q->y / s - a.y) * a.width;
    }
    if (q->x >= x0 && q->x < x1) ++row[work_column_[q->x - x0]];
  }
  for (int y = a.y; y < a.bottom(); ++y) {
    const std::int32_t* n_row = samples_.data() + static_cast<std::size_t>(y - a.y) * a.width;
    for (int x = a.x; x < a.right(); ++x) {
      const std::int32_t n = n_row[x - a.x];
      if (!n) continue;
      out.inside[regions_.row(y)[x]] += n;
      // Each region within one work pixel counts the samples once.
      std::int32_t seen[9];
      int k = 0;
      for (int yy = std::max(0, y - 1); yy <= std::min(h - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(w - 1, x + 1); ++xx) {
          const std::int32_t l = regions_.row(yy)[xx];
          if (l && std::find(seen, seen + k, l) == seen + k) seen[k++] = l;
        }
      for (int i = 0; i < k; ++i) out.near[seen[i]] += n;
    }
  }
}

bool ObjectFinder::moves(int l, const MotionCounts& m, const FinderParams& p, double share) const {
  const RegionStats& r = stats_[l];
  if (r.size <= 0 || static_cast<std::size_t>(l) >= m.inside.size()) return false;
  return m.inside[l] * m.per_sample >= share * p.min_moving * static_cast<double>(r.size) ||
         m.near[l] * m.per_sample >=
             share * p.min_moving_outline * 3.0 * static_cast<double>(r.outline);
}

void ObjectFinder::count_foreground(const FinderParams& p) {
  const ImageView& luma = work_.view().luma;
  const std::size_t n = static_cast<std::size_t>(luma.width) * luma.height;
  if (scene_rect_ != work_.rect() || scene_.size() != n) {
    scene_.assign(n, 0.f);
    scene_rect_ = work_.rect();
    scene_seen_ = 0;
  }
  const float rate = static_cast<float>(
      std::max(p.background_rate, 1.0 / (scene_seen_ + 1)));  // the first frames average
  const bool known = scene_seen_ >= p.background_frames;
  foreground_.assign(static_cast<std::size_t>(regions_.count()) + 1, 0);
  for (int y = 0; y < luma.height; ++y) {
    const std::uint8_t* in = luma.row(y);
    const std::int32_t* l = regions_.row(y);
    float* bg = scene_.data() + static_cast<std::size_t>(y) * luma.width;
    for (int x = 0; x < luma.width; ++x) {
      if (l[x] && (!known || std::abs(in[x] - bg[x]) > p.background_change)) ++foreground_[l[x]];
      bg[x] += rate * (in[x] - bg[x]);
    }
  }
  ++scene_seen_;
}

double ObjectFinder::foreground_share(const Mask& s, int scale, const FinderParams& p) const {
  return foreground_share(work_, s, scale, p);
}

double ObjectFinder::foreground_share(const WorkFrame& work, const Mask& s, int scale,
                                      const FinderParams& p) const {
  // A background of frames of another size (before a rescale) is none of these frames': read
  // with their layout, it would compare the wrong pixels, and past its end on larger frames.
  if (scene_seen_ < p.background_frames || scene_rect_.empty() || work.rect() != scene_rect_)
    return 1.0;
  const int fs = std::max(1, work.scale());
  const ImageView& luma = work.view().luma;
  double in = 0, differ = 0;
  for (int y = 0; y < s.rect().height; ++y) {
    for (int x = 0; x < s.rect().width; ++x) {
      if (!s.row(y)[x]) continue;
      // The finder's work pixel under this one's centre.
      const int fx = ((x + s.rect().x) * scale + scale / 2) / fs - scene_rect_.x;
      const int fy = ((y + s.rect().y) * scale + scale / 2) / fs - scene_rect_.y;
      if (fx < 0 || fy < 0 || fx >= luma.width || fy >= luma.height) continue;
      in += 1;
      const float bg = scene_[static_cast<std::size_t>(fy) * luma.width + fx];
      differ += std::abs(luma.at(fx, fy) - bg) > p.background_change;
    }
  }
  return in > 0 ? differ / in : 0.0;
}

double ObjectFinder::foreground_share(const ColorView& frame, const Mask& s, int scale,
                                      const FinderParams& p) const {
  load(frame, p, checked_);
  return foreground_share(checked_, s, scale, p);
}

void ObjectFinder::measure_regions() {
  stats_.assign(static_cast<std::size_t>(regions_.count()) + 1, {});
  bounds_.assign(stats_.size(), {});
  for (int y = 0; y < regions_.height(); ++y) {
    const std::int32_t* l = regions_.row(y);
    const std::int32_t* up = y > 0 ? regions_.row(y - 1) : nullptr;
    const std::int32_t* down = y + 1 < regions_.height() ? regions_.row(y + 1) : nullptr;
    const int w = regions_.width();
    for (int x = 0; x < w; ++x) {
      if (!l[x]) continue;
      RegionStats& r = stats_[l[x]];
      ++r.size;
      r.outline += x == 0 || x + 1 == w || !up || !down || l[x - 1] != l[x] || l[x + 1] != l[x] ||
                   up[x] != l[x] || down[x] != l[x];
      bounds_[l[x]].add(x, y);
    }
  }
  for (int l = 1; l <= regions_.count(); ++l) stats_[l].box = bounds_[l].rect();
}

template <class Keep>
Rect ObjectFinder::area_of(Keep&& keep) const {
  Rect area;
  for (int l = 1; l <= regions_.count(); ++l) {
    const Rect& b = stats_[l].box;
    if (keep(l, stats_[l])) area |= Rect{b.x - 1, b.y - 1, b.width + 2, b.height + 2};
  }
  return area;
}

template <class Score>
int ObjectFinder::best_region(Score&& score) const {
  int best = 0;
  double best_score = -1;
  for (int l = 1; l <= regions_.count(); ++l) {
    const double s = score(l, stats_[l]);
    if (s > best_score) best_score = s, best = l;
  }
  return best_score >= 0 ? best : 0;
}

int ObjectFinder::enclosing_region(Point2i p, int inner, double least) {
  measure_regions();
  int best = 0;
  for (int l = 1; l <= regions_.count(); ++l) {
    const RegionStats& r = stats_[l];
    if (l == inner || r.size < least || !r.box.contains(p)) continue;
    if (best && r.size >= stats_[best].size) continue;  // the innermost: the smallest
    copy_region(l, enclosure_);
    ops_.fill_holes(enclosure_);
    if (enclosure_.at(p)) best = l;
  }
  return best;
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

bool ObjectFinder::from_motion(const ColorView& frame, const MotionDetector::Motion& motion,
                               const MotionDetector::Motion& before, const FinderParams& p,
                               Mask& out, Point2i& seed, std::string& why) {
  load(frame, p, work_);
  foreground(p);
  const int w = candidates_.rect().width, h = candidates_.rect().height;
  const double frame_area = static_cast<double>(w) * h;
  regions_.label(candidates_.view(), false);
  count_foreground(p);
  measure_regions();
  // Size, the border and the background first: motion is counted only around what passes them.
  const auto may_be = [&](int l, const RegionStats& r) {
    const Rect& b = r.box;
    const double size = static_cast<double>(r.size);
    return size >= p.min_area * frame_area && size <= p.max_area * frame_area && b.x > 0 &&
           b.y > 0 && b.right() < w && b.bottom() < h && foreground_[l] >= p.min_foreground * size;
  };
  count_motion(motion, area_of(may_be), moving_);
  const int label = best_region([&](int l, const RegionStats& r) {
    if (!may_be(l, r) || !moves(l, moving_, p)) return -1.0;
    return moving_.inside[l] * moving_.per_sample /
           (static_cast<double>(r.box.width) * r.box.height);
  });
  if (!label) {
    why = kNoMovingRegion;
    return false;
  }
  count_motion(before, area_of([&](int l, const RegionStats&) { return l == label; }),
               moving_before_);
  if (!moves(label, moving_before_, p, 0.5)) {
    why = "what moves there did not move on the last frame: waiting";
    return false;
  }
  copy_region(label, out);
  seed = to_frame_pixel(ops_.deepest(out).first, work_.scale());
  return true;
}

bool ObjectFinder::from_moving_blob(const ColorView& frame, const MotionDetector::Motion& motion,
                                    const MotionDetector::Motion& before, const FinderParams& p,
                                    Mask& out, Point2i& seed, std::string& why) {
  // The work frame from_motion() built from this frame: built again, it cost a search at 1080p a
  // third more.
  const int w = work_.rect().width, h = work_.rect().height, s = work_.scale();
  // Where the frame changed, at the finder's scale, its samples joined across their spacing.
  blobs_.reset({0, 0, w, h});
  for (const Point2i& q : motion.points)
    if (q.x / s < w && q.y / s < h) blobs_.row(q.y / s)[q.x / s] = 1;
  ops_.dilate(blobs_, std::max(1, (motion.step + s - 1) / s), opened_);
  regions_.label(opened_.view(), false);
  measure_regions();
  const double frame_area = static_cast<double>(w) * h;
  const int label = best_region([&](int, const RegionStats& r) {
    const Rect& b = r.box;
    const bool in_view = b.x > 0 && b.y > 0 && b.right() < w && b.bottom() < h;
    // What changed is the object's outline as it moves: its box, not its pixels, is its size.
    const double size = static_cast<double>(b.width) * b.height;
    if (!in_view || size < p.min_area * frame_area || size > p.max_area * frame_area) return -1.0;
    return static_cast<double>(r.size);  // the largest moving blob wholly in view
  });
  if (!label) {
    why = "nothing that moves is wholly in view";
    return false;
  }
  // It moved on the last frame that showed motion too (a repeated frame shows none).
  const Rect box = stats_[label].box;
  std::size_t moved_before = 0;
  for (const Point2i& q : before.points) moved_before += box.contains({q.x / s, q.y / s});
  if (static_cast<double>(moved_before) * before.step * before.step <
      0.5 * p.min_moving * static_cast<double>(stats_[label].size) * s * s) {
    why = "what moves there did not move on the last frame: waiting";
    return false;
  }
  // The moving blob is a box around the object and where it was: the object is found in it as
  // in a user's box, by its colours.
  const Rect frame_box = to_frame(box, s, frame.luma.width, frame.luma.height);
  if (!around_seed({frame_box.x + frame_box.width / 2, frame_box.y + frame_box.height / 2}, p, &box,
                   out, why) ||
      moments(out).area < 0.2 * box.width * box.height) {
    why = "what moves there has no colours of its own";
    return false;
  }
  if (!mask_moves(out, motion, p) || within_apart_region(out)) {
    why = "what moves there is a part of a larger region that hardly moves";
    return false;
  }
  seed = to_frame_pixel(ops_.deepest(out).first, s);
  return true;
}

bool ObjectFinder::within_apart_region(const Mask& m) {
  ops_.dilate(m, 1, enclosure_);
  const Rect& r = enclosure_.rect();
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const Point2i c{x + r.x, y + r.y};
      if (enclosure_.row(y)[x] && !m.at(c) && !candidates_.at(c)) return false;
    }
  return true;
}

bool ObjectFinder::mask_moves(const Mask& m, const MotionDetector::Motion& motion,
                              const FinderParams& p) {
  const int s = work_.scale();
  ops_.dilate(m, 1, enclosure_);
  std::int64_t inside = 0, near = 0, size = 0, outline = 0;
  for (const Point2i& q : motion.points) {
    const Point2i w{q.x / s, q.y / s};
    inside += m.at(w);
    near += enclosure_.at(w);
  }
  const Rect& r = m.rect();
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      if (!m.row(y)[x]) continue;
      ++size;
      const Point2i c{x + r.x, y + r.y};
      outline += !m.at({c.x - 1, c.y}) || !m.at({c.x + 1, c.y}) || !m.at({c.x, c.y - 1}) ||
                 !m.at({c.x, c.y + 1});
    }
  const double per_sample = static_cast<double>(motion.step) * motion.step / (1.0 * s * s);
  return inside * per_sample >= p.min_moving * static_cast<double>(size) ||
         near * per_sample >= p.min_moving_outline * 3.0 * static_cast<double>(outline);
}

bool ObjectFinder::from_model(const ColorView& frame, const AppearanceModel& model,
                              const MotionDetector::Motion& motion, double area, double factor,
                              Point2d near, const FinderParams& p, Mask& out, Point2i& seed,
                              std::string& why) {
  load(frame, p, work_);
  const int w = work_.rect().width, h = work_.rect().height, s = work_.scale();
  model.likelihood(work_.view(), {0, 0}, {0, 0, w, h}, like_);
  candidates_.reset({0, 0, w, h});
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* l = like_.data() + static_cast<std::size_t>(y) * w;
    std::uint8_t* c = candidates_.row(y);
    for (int x = 0; x < w; ++x) c[x] = l[x] >= 128;
  }
  ops_.erode(candidates_, 1, opened_);
  ops_.dilate(opened_, 1, candidates_);
  regions_.label(candidates_.view(), false);
  count_foreground(p);
  measure_regions();
  const double work_area = area / (static_cast<double>(s) * s);
  const double diagonal = std::hypot(w, h);
  const Point2d near_work{near.x / s, near.y / s};
  const auto may_be = [&](int l, const RegionStats& r) {
    const double size = static_cast<double>(r.size);
    return size >= work_area / factor && size <= work_area * factor &&
           foreground_[l] >= p.min_foreground * size;
  };
  count_motion(motion, area_of(may_be), moving_);
  const int label = best_region([&](int l, const RegionStats& r) {
    if (!may_be(l, r) || !moves(l, moving_, p)) return -1.0;
    const Point2d c{r.box.x + r.box.width / 2.0, r.box.y + r.box.height / 2.0};
    return 1.0 - distance(c, near_work) / diagonal;  // nearest first
  });
  if (!label) {
    why = "nothing of the object's colours and size moves";
    return false;
  }
  copy_region(label, out);
  seed = to_frame_pixel(ops_.deepest(out).first, s);
  return true;
}

}  // namespace projtrack
