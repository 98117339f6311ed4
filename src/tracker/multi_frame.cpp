// One frame of a MultiTracker: the checks every object shares, each object's look at the frame's
// one evidence within its share of the frame's budget, the pixels two objects claim given to the
// one in front, and each object's verdict.
#include <algorithm>
#include <numeric>
#include <utility>

#include "tracker/multi_tracker_impl.hpp"
#include "tracker/overlaps.hpp"

namespace projtrack {

namespace {

// An object's share of what is left of the frame's `limit` after `spent`, among `objects` left.
std::uint64_t share_of(std::uint64_t limit, std::uint64_t spent, std::size_t objects) {
  if (limit == WorkBudget::kUnlimited) return limit;
  return (limit - std::min(spent, limit)) / std::max<std::size_t>(objects, 1);
}

}  // namespace

std::vector<std::size_t> MultiTracker::Impl::look_order() const {
  std::vector<std::size_t> order(objects.size());
  std::iota(order.begin(), order.end(), 0);
  // Each object takes at most an equal share of what those before it left: in the order of what
  // they cost on the last frame, the cheap ones leave what they do not need to the dear ones.
  const auto cost = [&](std::size_t i) {
    return objects[i].track.model->tracking() ? objects[i].last_work : WorkBudget::kUnlimited;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost(a) < cost(b); });
  // But the user's first start not taken yet goes first, with the whole budget: behind the
  // followed objects it might never find enough left (they follow at a coarser scale for that
  // frame instead). Only while its refusals are within the patience: a start that keeps failing
  // takes its turn last.
  const auto first = std::find_if(order.begin(), order.end(), [&](std::size_t i) {
    const Track& t = objects[i].track.state.track();
    return !objects[i].track.model->tracking() && !t.last && t.inner &&
           t.refused_in_a_row <= patience;
  });
  if (first != order.end()) std::rotate(order.begin(), first, first + 1);
  return order;
}

namespace {

// Whether a look is a silhouette that can meet another's.
bool has_silhouette(const Look& l) {
  return !l.done && l.observation.kind == Observation::Kind::Silhouette;
}

}  // namespace

std::vector<int> MultiTracker::Impl::settle_overlaps(std::vector<Look>& looks) {
  const std::size_t n = objects.size();
  std::vector<int> front_of(n, 0), beside(n, 0);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (!has_silhouette(looks[a]) || !has_silhouette(looks[b])) continue;
      ObjectModel& ma = *objects[a].track.model;
      ObjectModel& mb = *objects[b].track.model;
      const SilhouetteMask sa = ma.silhouette(width, height), sb = mb.silhouette(width, height);
      if ((frame_rect(sa) & frame_rect(sb)).empty()) continue;
      beside[a] = objects[b].id;
      beside[b] = objects[a].id;
      const FramePixels both = shared_pixels(sa, sb);
      if (both.empty()) continue;
      const bool a_in_front = ma.explains(both) >= mb.explains(both);
      const std::size_t behind = a_in_front ? b : a;
      ObjectModel& m = a_in_front ? mb : ma;
      looks[behind].observation = m.give_up(both, looks[behind].observation);
      front_of[behind] = objects[a_in_front ? a : b].id;
    }
  }
  // An object that lost more than half its area since it met another is hidden by it.
  std::vector<int> hidden_by(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    Object& o = objects[i];
    const Track& t = o.track.state.track();
    const bool met_before = o.met;
    o.met = beside[i] != 0;
    if (!o.met || looks[i].starting || !t.last) continue;
    if (!met_before) o.area_before_met = t.last->area;
    const double left =
        has_silhouette(looks[i]) ? silhouette_area(o.track.model->silhouette(width, height)) : 0;
    if (left < 0.5 * o.area_before_met) hidden_by[i] = front_of[i] ? front_of[i] : beside[i];
  }
  return hidden_by;
}

bool MultiTracker::Impl::still_covers(int front, std::size_t i) const {
  const Object* f = find(front);
  const Track& t = objects[i].track.state.track();
  return f && t.last && covers_half_of(f->track.model->silhouette(width, height), t.last->bbox);
}

int MultiTracker::Impl::covering(std::size_t i, const std::vector<bool>& followed) const {
  const Track& t = objects[i].track.state.track();
  if (!t.last) return 0;
  for (std::size_t j = 0; j < objects.size(); ++j)
    if (j != i && followed[j] &&
        covers_half_of(objects[j].track.model->silhouette(width, height), t.last->bbox))
      return objects[j].id;
  return 0;
}

TrackResult MultiTracker::Impl::conclude(std::size_t i, int hidden_by, int covered_by,
                                         FrameEvidence& ev, const FrameInput& in,
                                         const Look& look) {
  Object& o = objects[i];
  ObjectTrack& t = o.track;
  // Hidden before: found again once more than half of it shows, or out from behind that object.
  const double seen =
      has_silhouette(look) ? silhouette_area(t.model->silhouette(width, height)) : 0;
  if (!hidden_by && o.hidden_by && seen < 0.5 * o.area_before_met && still_covers(o.hidden_by, i))
    hidden_by = o.hidden_by;
  if (!hidden_by) {
    t.covered_by = covered_by;
    TrackResult r = t.conclude(ev, in, look);
    t.covered_by = 0;
    if (has_features(r.status)) o.hidden_by = 0;  // found again
    return r;
  }
  // Hidden: the model keeps the object's colours, not where the picture's motion (the object in
  // front's) would carry it; it looks for it again by its colours near where it was.
  t.model->settle(Verdict::Refused);
  t.model->forget(Forget::Position);
  o.hidden_by = hidden_by;
  return t.occluded("object " + std::to_string(hidden_by) + " is in front of it");
}

namespace {

TrackResult failed(TrackStatus status, const std::string& why) {
  TrackResult r;
  r.status = status;
  r.detail = why;
  return r;
}

}  // namespace

std::vector<TrackResult> MultiTracker::Impl::track(const ColorView& frame, EdgeSource& edges,
                                                   const FrameInput& in) {
  const std::uint64_t limit = frame_work_limit(frame.luma.width, frame.luma.height, in.tp);
  work.budget = WorkBudget(limit, stop);
  width = frame.luma.width;
  height = frame.luma.height;
  edges.set_budget(&work.budget);
  if (in.trace) in.trace->clear();
  const std::size_t n = objects.size();
  std::vector<TrackResult> results(n);
  TrackStatus status;
  const std::string bad = frame_problem(frame, edges, in, work.budget, status);
  std::vector<Look> looks(n);
  std::vector<WorkBudget> shares(n, work.budget);
  for (std::size_t i = 0; i < n; ++i) {
    if (!bad.empty()) {
      looks[i].done = failed(status, bad);
    } else if (work.budget.interrupted()) {  // nothing is started while the stop flag is set
      looks[i].done.emplace();
      objects[i].track.stopped(Features{}, work.budget, in.tp, *looks[i].done);
    }
  }
  if (bad.empty() && !work.budget.interrupted()) {
    const ObjectModelKind kind = model_for(edges, in.tp);
    for (Object& o : objects) o.track.use_model(kind);
    FrameEvidence ev(frame, edges, work.budget, work.estimator(in.method), in.method, in.params,
                     in.tp, in.trace, work.images);
    patience = in.tp.patience;
    const std::vector<std::size_t> order = look_order();
    std::uint64_t spent = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = order[k];
      // A start takes all that is left: starts that share a frame's budget might each fall
      // short on every frame; taken whole, one start a frame at least goes through.
      const bool starts = !objects[i].track.model->tracking();
      work.budget = WorkBudget(share_of(limit, spent, starts ? 1 : n - k), stop);
      looks[i] = objects[i].track.look(ev, in);
      shares[i] = work.budget;
      spent += work.budget.spent();
    }
    const std::vector<int> hidden_by = settle_overlaps(looks);
    std::vector<bool> followed(n);  // before any verdict: which objects cover others this frame
    for (std::size_t i = 0; i < n; ++i)
      followed[i] = has_silhouette(looks[i]) && !looks[i].starting;
    for (std::size_t i : order) {
      if (looks[i].done) continue;
      work.budget = shares[i];
      looks[i].done = conclude(i, hidden_by[i], covering(i, followed), ev, in, looks[i]);
      shares[i] = work.budget;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    TrackResult& r = results[i];
    r = std::move(*looks[i].done);
    r.id = objects[i].id;
    r.inner_point = objects[i].track.state.track().inner;
    r.work = shares[i].spent();
    objects[i].last_work = r.work;
    r.work_limit = shares[i].limit();
    r.gesture = objects[i].track.state.pointer.take_gesture();
  }
  return results;
}

}  // namespace projtrack
