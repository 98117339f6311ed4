#include "tracker/silhouette_pieces.hpp"

#include <algorithm>

namespace projtrack {

int SilhouettePieces::split(const Mask& s, int neck, double min_share) {
  rect_ = s.rect();
  silhouette_ = &s;
  const int w = rect_.width, h = rect_.height;
  order_.clear();
  owner_.assign(static_cast<std::size_t>(w) * h, 0);
  const double area = moments(s).area;
  if (area <= 0) return 0;
  ops_.erode(s, std::max(0, neck), tmp_);
  ops_.dilate(tmp_, std::max(0, neck), opened_);
  cores_.label(opened_.view(), false);
  label_of_.assign(static_cast<std::size_t>(cores_.count()) + 1, -1);
  for (int l = 1; l <= cores_.count(); ++l)
    if (cores_.size(l) >= min_share * area) order_.push_back(l);
  std::sort(order_.begin(), order_.end(),
            [&](int a, int b) { return cores_.size(a) > cores_.size(b); });
  queue_.clear();
  for (std::size_t i = 0; i < order_.size(); ++i) label_of_[order_[i]] = static_cast<int>(i);
  for (int y = 0; y < h; ++y) {
    const std::int32_t* l = cores_.row(y);
    for (int x = 0; x < w; ++x) {
      if (!l[x] || label_of_[l[x]] < 0) continue;
      owner_[static_cast<std::size_t>(y) * w + x] = label_of_[l[x]] + 1;
      queue_.push_back({x, y});
    }
  }
  if (order_.empty()) {  // too thin to open anywhere: one piece, the whole silhouette
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) owner_[static_cast<std::size_t>(y) * w + x] = s.row(y)[x];
    order_.push_back(0);
    return 1;
  }
  // Grown back breadth first over the silhouette: each pixel goes to the nearest core.
  grow();
  // A part of the silhouette with no core (thinner than the neck everywhere) and big enough is a
  // piece of its own.
  leftover_.reset(rect_);
  bool any = false;
  for (int y = 0; y < h; ++y) {
    const std::int32_t* o = owner_.data() + static_cast<std::size_t>(y) * w;
    std::uint8_t* d = leftover_.row(y);
    for (int x = 0; x < w; ++x) any |= (d[x] = s.row(y)[x] && !o[x]) != 0;
  }
  if (!any) return static_cast<int>(order_.size());
  rest_.label(leftover_.view(), false);
  for (int l = 1; l <= rest_.count(); ++l) {
    if (rest_.size(l) < min_share * area) continue;
    const int index = static_cast<int>(order_.size());
    order_.push_back(-l);  // a leftover: its own pixels are its core
    for (int y = 0; y < h; ++y) {
      const std::int32_t* c = rest_.row(y);
      for (int x = 0; x < w; ++x)
        if (c[x] == l) owner_[static_cast<std::size_t>(y) * w + x] = index + 1;
    }
  }
  return static_cast<int>(order_.size());
}

void SilhouettePieces::grow() {
  const Mask& s = *silhouette_;
  const int w = rect_.width, h = rect_.height;
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const Point2i p = queue_[head];
    const std::int32_t o = owner_[static_cast<std::size_t>(p.y) * w + p.x];
    const Point2i next[4] = {{p.x - 1, p.y}, {p.x + 1, p.y}, {p.x, p.y - 1}, {p.x, p.y + 1}};
    for (const Point2i& q : next) {
      if (q.x < 0 || q.y < 0 || q.x >= w || q.y >= h || !s.row(q.y)[q.x]) continue;
      std::int32_t& owner = owner_[static_cast<std::size_t>(q.y) * w + q.x];
      if (owner) continue;
      owner = o;
      queue_.push_back(q);
    }
  }
}

int SilhouettePieces::whole(const Mask& s) {
  rect_ = s.rect();
  order_.assign(1, 0);
  owner_.resize(static_cast<std::size_t>(rect_.width) * rect_.height);
  bool any = false;
  for (int y = 0; y < rect_.height; ++y) {
    const std::uint8_t* in = s.row(y);
    std::int32_t* o = owner_.data() + static_cast<std::size_t>(y) * rect_.width;
    for (int x = 0; x < rect_.width; ++x) any |= (o[x] = in[x]) != 0;
  }
  if (!any) order_.clear();
  return any ? 1 : 0;
}

const Mask& SilhouettePieces::piece(int i) {
  piece_.reset(rect_);
  for (int y = 0; y < rect_.height; ++y) {
    const std::int32_t* o = owner_.data() + static_cast<std::size_t>(y) * rect_.width;
    std::uint8_t* d = piece_.row(y);
    for (int x = 0; x < rect_.width; ++x) d[x] = o[x] == i + 1;
  }
  return piece_;
}

Point2i SilhouettePieces::deepest(int i) {
  if (order_[i] <= 0) return ops_.deepest(piece(i)).first;  // the whole, or a leftover
  core_.reset(rect_);
  for (int y = 0; y < rect_.height; ++y) {
    const std::int32_t* l = cores_.row(y);
    std::uint8_t* d = core_.row(y);
    for (int x = 0; x < rect_.width; ++x) d[x] = l[x] == order_[i];
  }
  return ops_.deepest(core_).first;
}

int SilhouettePieces::piece_at(Point2i p) const {
  if (!rect_.contains(p)) return -1;
  return owner_[static_cast<std::size_t>(p.y - rect_.y) * rect_.width + (p.x - rect_.x)] - 1;
}

}  // namespace projtrack
