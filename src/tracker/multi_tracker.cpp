// MultiTracker: objects added and removed, each an ObjectTrack with its own id.
#include <algorithm>
#include <cmath>
#include <utility>

#include "tracker/multi_tracker_impl.hpp"

namespace projtrack {

MultiTracker::MultiTracker(std::size_t max_objects) : impl_(std::make_unique<Impl>()) {
  impl_->max_objects = std::max<std::size_t>(max_objects, 1);
}
MultiTracker::~MultiTracker() = default;
MultiTracker::MultiTracker(MultiTracker&&) noexcept = default;
MultiTracker& MultiTracker::operator=(MultiTracker&&) noexcept = default;

MultiTracker::Impl::Object* MultiTracker::Impl::find(int id) {
  for (Object& o : objects)
    if (o.id == id) return &o;
  return nullptr;
}
const MultiTracker::Impl::Object* MultiTracker::Impl::find(int id) const {
  return const_cast<Impl*>(this)->find(id);
}

namespace {

// Where object `t` is now, for a new start to be checked against: its silhouette, else its last
// box, else (a start not taken yet) its user's box, else its user's point.
bool is_on(const ObjectTrack& t, Point2i p, int width, int height) {
  const Track& k = t.state.track();
  const SilhouetteMask s = t.model->silhouette(width, height);
  if (k.last && !s.empty()) return s.contains(p);
  if (k.last) return k.last->bbox.contains(p);
  if (k.seed_box) return k.seed_box->contains(p);
  if (!k.inner) return false;
  // A point not started yet: a start that near it is the same object.
  const double near = 0.02 * std::min(width, height);
  return std::hypot(p.x - k.inner->x, p.y - k.inner->y) <= near;
}

}  // namespace

std::string MultiTracker::Impl::why_not_new(Point2i p, const Rect* box, int w, int h) const {
  if (w <= 0 || h <= 0) return "the frame has no size";
  if (objects.size() >= max_objects)
    return "already following " + std::to_string(objects.size()) + " objects, max-objects";
  for (const Object& o : objects) {
    const bool pending_here = box && !o.track.state.track().last && o.track.state.track().inner &&
                              box->contains(*o.track.state.track().inner);
    if (is_on(o.track, p, w, h) || pending_here)
      return "object " + std::to_string(o.id) + " is there already";
  }
  return {};
}

Added MultiTracker::Impl::add(Object&& o) {
  o.id = next_id++;
  o.track.keeps_looking = true;
  objects.push_back(std::move(o));
  return Added{objects.back().id, {}};
}

Added MultiTracker::add_point(Point2i p, int width, int height) {
  if (!Rect{0, 0, width, height}.contains(p))
    return {0, "the point (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                   ") lies outside the " + std::to_string(width) + "×" + std::to_string(height) +
                   " frame"};
  if (std::string why = impl_->why_not_new(p, nullptr, width, height); !why.empty())
    return {0, std::move(why)};
  Impl::Object o;
  o.track.seed(p);
  return impl_->add(std::move(o));
}

Added MultiTracker::add_box(const Rect& box, int width, int height) {
  const Rect frame{0, 0, width, height};
  if (box.empty())
    return {
        0, "the box " + std::to_string(box.width) + "×" + std::to_string(box.height) + " is empty"};
  const Point2i centre{box.x + box.width / 2, box.y + box.height / 2};
  if (!frame.contains(centre))
    return {0, "the box's centre (" + std::to_string(centre.x) + ", " + std::to_string(centre.y) +
                   ") lies outside the " + std::to_string(width) + "×" + std::to_string(height) +
                   " frame"};
  if (std::string why = impl_->why_not_new(centre, &box, width, height); !why.empty())
    return {0, std::move(why)};
  Impl::Object o;
  o.track.seed_box(box);
  return impl_->add(std::move(o));
}

Added MultiTracker::add_mask(const ImageView& mask) {
  Impl::Object o;
  if (!o.track.seed_mask(mask))
    return {0, "the mask holds no object pixel, or has no usable shape (no data, stride < width)"};
  const Track& t = o.track.state.track();
  if (std::string why = impl_->why_not_new(*t.inner, &*t.seed_box, mask.width, mask.height);
      !why.empty())
    return {0, std::move(why)};
  return impl_->add(std::move(o));
}

bool MultiTracker::remove(int id) {
  auto& v = impl_->objects;
  const auto it =
      std::find_if(v.begin(), v.end(), [id](const Impl::Object& o) { return o.id == id; });
  if (it == v.end()) return false;
  v.erase(it);
  return true;
}

void MultiTracker::clear() { impl_->objects.clear(); }
std::size_t MultiTracker::size() const { return impl_->objects.size(); }
std::size_t MultiTracker::max_objects() const { return impl_->max_objects; }
bool MultiTracker::contains(int id) const { return impl_->find(id) != nullptr; }

std::vector<int> MultiTracker::ids() const {
  std::vector<int> ids;
  for (const Impl::Object& o : impl_->objects) ids.push_back(o.id);
  return ids;
}

SilhouetteMask MultiTracker::silhouette(int id) const {
  const Impl::Object* o = impl_->find(id);
  if (!o || !o->track.state.track().last) return {};
  return o->track.model->silhouette(impl_->width, impl_->height);
}

void MultiTracker::set_stop_flag(const std::atomic<bool>* stop) { impl_->stop = stop; }

void MultiTracker::rescale(int width, int height, int new_width, int new_height) {
  if (width <= 0 || height <= 0 || new_width <= 0 || new_height <= 0) return;
  for (Impl::Object& o : impl_->objects)
    o.track.rescale(static_cast<double>(new_width) / width,
                    static_cast<double>(new_height) / height, new_width, new_height);
}

void MultiTracker::relearn() {
  for (Impl::Object& o : impl_->objects) o.track.relearn();
}

std::vector<TrackResult> MultiTracker::track(const ColorView& frame, const EdgeParams& edge_params,
                                             double t, Method m, const Params& params,
                                             const TrackerParams& tp, Trace* trace) {
  EdgeSource edges(impl_->work.edge_map, frame.luma, edge_params);
  return impl_->track(frame, edges, FrameInput{t, m, params, tp, trace});
}

std::vector<TrackResult> MultiTracker::track(const ImageView& gray, const EdgeParams& edge_params,
                                             double t, Method m, const Params& params,
                                             const TrackerParams& tp, Trace* trace) {
  return track(ColorView{gray, {}, {}}, edge_params, t, m, params, tp, trace);
}

std::vector<TrackResult> MultiTracker::track(const ColorView& frame, double t, const Settings& s,
                                             Trace* trace) {
  return track(frame, s.edges, t, s.method, s.params, s.tracker, trace);
}

std::vector<TrackResult> MultiTracker::track(const ImageView& gray, double t, const Settings& s,
                                             Trace* trace) {
  return track(ColorView{gray, {}, {}}, s.edges, t, s.method, s.params, s.tracker, trace);
}

}  // namespace projtrack
