// The flow model's start when nobody points at the object: the frame's centre, the object lost
// before found again by its colours, or the object that moves apart from the picture's motion.
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "models/flow/flow_object_model.hpp"
#include "segmentation/box_start.hpp"

namespace projtrack {

namespace {

// Work units a work pixel of the whole frame costs the colour search: the colours' log-odds, the
// pieces, the difference with the last frame searched (as the estimators' units: about a ns).
constexpr std::uint64_t kColourSearchCost = 12;
// A piece of the object's colours is the object when they say so by this much on average
// (nats): more than a patch that merely shares some of them.
constexpr double kLeastMeanOdds = 1.0;
// ...when this share of it changed since the last frame searched (it moves: a static region of
// its colours is the background's)...
constexpr double kLeastMovedShare = 0.05;
// ...and it lies within this many times √(its lost area) of where it was lost.
constexpr double kReach = 4.0;
// The object cut out of a moving region's box stands for the region when their intersection over
// union is at least this: a cut that took something else in the box keeps the region.
constexpr double kLeastRefinedOverlap = 0.5;

// The median of CV_8U `m` and its median absolute deviation, by histogram.
std::array<int, 2> median_and_spread(const cv::Mat& m) {
  std::array<int, 256> h{};
  for (int y = 0; y < m.rows; ++y) {
    const std::uint8_t* p = m.ptr<std::uint8_t>(y);
    for (int x = 0; x < m.cols; ++x) ++h[p[x]];
  }
  const auto median_of = [&](const std::array<int, 256>& counts) {
    const long half = static_cast<long>(m.total()) / 2;
    long seen = 0;
    for (int v = 0; v < 256; ++v)
      if ((seen += counts[v]) > half) return v;
    return 255;
  };
  const int median = median_of(h);
  std::array<int, 256> deviations{};
  for (int v = 0; v < 256; ++v) deviations[std::abs(v - median)] += h[v];
  return {median, median_of(deviations)};
}

}  // namespace

bool FlowObjectModel::changed_since_last(const cv::Mat& gray) {
  const bool comparable = last_searched_.size() == gray.size();
  if (comparable) {
    cv::absdiff(gray, last_searched_, moved_);
    // Beyond the frame's own noise: its median difference and six robust spreads more.
    const std::array<int, 2> m = median_and_spread(moved_);
    const double noise = m[0] + 6 * 1.4826 * std::max(m[1], 1);
    cv::compare(moved_, noise, moved_, cv::CMP_GT);
  }
  gray.copyTo(last_searched_);
  return comparable;
}

bool FlowObjectModel::find_by_colours(FrameEvidence& ev, Point2d near, double area_expected,
                                      const WorkImages& whole, const cv::Mat& moved) {
  const ColourMixture& colours = segmenter_.colours();
  if (!colours.learned() || !(area_expected > 0)) return false;
  colour_odds_ = cv::Mat::zeros(whole.size(), CV_32F);
  colours.add_evidence(whole.bgr, ev.tp.flow.first_share, colour_odds_);
  colours.known_object_colours(whole.bgr, known_);
  cv::Mat object = (colour_odds_ > 0) & known_;
  const int n = cv::connectedComponentsWithStats(object, pieces_, piece_stats_, piece_centres_, 8);
  const double s2 = static_cast<double>(whole.scale) * whole.scale;
  const double leak = ev.tp.leak_factor * ev.tp.leak_factor;
  const double reach = kReach * std::sqrt(area_expected);
  int best = 0;
  double nearest = reach;
  for (int i = 1; i < n; ++i) {
    const double area = piece_stats_.at<int>(i, cv::CC_STAT_AREA) * s2;
    if (area < area_expected / leak || area > area_expected * leak) continue;
    const double dx = (piece_centres_.at<double>(i, 0) + 0.5) * whole.scale - near.x;
    const double dy = (piece_centres_.at<double>(i, 1) + 0.5) * whole.scale - near.y;
    const double distance = std::hypot(dx, dy);
    if (distance >= nearest) continue;
    const cv::Mat piece = pieces_ == i;
    if (cv::mean(colour_odds_, piece)[0] < kLeastMeanOdds) continue;
    const double area_work = piece_stats_.at<int>(i, cv::CC_STAT_AREA);
    if (!moved.empty() && cv::countNonZero(moved & piece) < kLeastMovedShare * area_work) continue;
    best = i;
    nearest = distance;
  }
  if (best == 0) return false;
  cv::compare(pieces_, best, inside_, cv::CMP_EQ);
  return true;
}

FirstSilhouette FlowObjectModel::search(FrameEvidence& ev, const Track& track,
                                        const WorkImages& whole) {
  FirstSilhouette out;
  const TrackerParams& tp = ev.tp;
  if (tp.acquisition == Acquisition::Center) {
    StartRequest centre;
    centre.from = StartRequest::From::Point;
    centre.point = {ev.width() / 2, ev.height() / 2};
    out = first_silhouette(ev, centre, track, whole);
    if (!out.found) out.why = "at the frame centre: " + out.why;
    return out;
  }
  // Not seen for long: its colours are forgotten, and any moving object is looked for.
  if (segmenter_.colours().learned() && searched_ >= tp.forget_after) {
    segmenter_.forget(true);
    searched_ = 0;
  }
  ++searched_;
  const std::uint64_t cost = kColourSearchCost * static_cast<std::uint64_t>(whole.size().area());
  if (ev.budget.exhausted(cost)) return out;
  ev.budget.spend(cost);
  // An object that left the frame comes back partly in view: its area is judged against the
  // largest the track saw, not the sliver it was last seen as.
  const double area = std::max(track.lost_area, largest_area_);
  if (changed_since_last(whole.gray) &&
      find_by_colours(ev, track.lost_centroid, area, whole, moved_)) {
    out.found = out.resumed = true;
    return out;
  }
  out.found = moving_.find(whole.gray, ev.budget, inside_, out.why);
  if (out.found) refine_in_box(ev, whole);
  return out;
}

FirstSilhouette FlowObjectModel::find_again(FrameEvidence& ev, const Track& track,
                                            const WorkImages& whole) {
  FirstSilhouette out;
  out.why = "the object is looked for near where it was lost, by its colours";
  if (!track.last) return out;
  const std::uint64_t cost = kColourSearchCost * static_cast<std::uint64_t>(whole.size().area());
  if (ev.budget.exhausted(cost)) return out;
  ev.budget.spend(cost);
  const double area = std::max(track.last->area, largest_area_);
  out.found = find_by_colours(ev, track.last->centroid, area, whole, cv::Mat());
  if (out.found) out.why.clear();
  return out;
}

void FlowObjectModel::refine_in_box(FrameEvidence& ev, const WorkImages& whole) {
  // What moves apart is the object's changing part, or its hull: the object itself is cut out of
  // that region's box, as from a user's box, when the cut keeps most of the region.
  const cv::Rect b = cv::boundingRect(inside_);
  const int s = whole.scale;
  const Rect box =
      clip_to_frame({b.x * s, b.y * s, b.width * s, b.height * s}, ev.width(), ev.height());
  const StartOutcome cut = object_in_box(ev.frame, box, ev.tp.flow.box_pixels, whole.size(),
                                         cut_work_, ev.budget, refined_);
  if (cut.kind != StartOutcome::Kind::Cut) return;
  const double both = cv::countNonZero(refined_ & inside_);
  if (both >= kLeastRefinedOverlap * cv::countNonZero(inside_ | refined_))
    cv::swap(inside_, refined_);
}

}  // namespace projtrack
