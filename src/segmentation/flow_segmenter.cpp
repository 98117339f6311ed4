#include "segmentation/flow_segmenter.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "motion/motion_evidence.hpp"

namespace projtrack {

namespace {

// The flow's pyramid level for an object of `area` work px, now read at `current`: the coarsest
// (no coarser than DIS's preset's) at which it spans `span` px (√area), or a small object is a
// speck there and its pixels move with what surrounds them. A coarser level is taken only where
// it would span 1.5 × `span`, so that an object near the limit does not switch every frame.
int flow_level(double area, int current, double span) {
  const double across = std::sqrt(std::max(area, 0.0));
  const auto spans = [&](int level, double least) { return across / (1 << level) >= least; };
  int needed = DenseFlow::kPresetLevel;
  while (needed > 0 && !spans(needed, span)) --needed;
  if (needed <= current) return needed;
  int level = current;
  while (level < needed && spans(level + 1, 1.5 * span)) ++level;
  return level;
}

}  // namespace

void FlowSegmenter::start(const WorkImages& whole, const cv::Mat& whole_inside,
                          const WorkImages& img, const cv::Mat& inside, const FlowModelParams& p,
                          bool outlined, bool refine) {
  scale_ = img.scale;
  cv::compare(inside, 0, mask_, cv::CMP_GT);
  box_ = last_box_ = cv::boundingRect(mask_);
  mask_.convertTo(last_, CV_32F, 1.0 / 255);
  last_.copyTo(memory_);
  memory_box_ = box_;
  prior_ = cv::Mat::zeros(img.size(), CV_32F);
  prior_box_ = cv::Rect();
  fullest_ = area_ = cv::sum(last_(box_))[0];
  colours_.start(whole.bgr, whole_inside);
  local_colours_.forget();
  outlined_ = outlined;
  relearn_ = false;
  if (outlined && p.local_colour_weight > 0) {
    const cv::Rect near = colour_ring(p);
    local_colours_.learn(img.bgr, near, mask_(near), around_, p.local_colour_cells);
  }
  if (refine) refine_start(img, p);
  flow_.reset();
  flow_level_ = flow_level(area_, DenseFlow::kPresetLevel, p.flow_span);
  flow_.compute(img.gray, flow_level_, cv::Rect(), img.filled);
}

void FlowSegmenter::refine_start(const WorkImages& img, const FlowModelParams& p) {
  // The first silhouette as its own prior, narrowly blurred (a start's cut is right to within a
  // few of its cells), cut again at the object's scale by the colours just learned: its outline
  // then lies where the colours part, not on the start's coarser cells.
  prior_(box_).setTo(1.0f, mask_(box_));
  prior_box_ = box_;
  cv::compare(prior_, 0.5, inside_, cv::CMP_GT);
  split_ = MotionSplit{};
  const int blur = static_cast<int>(kRefineSpread * std::sqrt(std::max(area_, 1.0))) | 1;
  reach_ = reach_of_prior(2 * blur);
  weigh_evidence(img, blur, p);
  cv::Mat cut = mask_(reach_);
  cut.setTo(0);
  cv::compare(log_odds_(reach_), 0, cut, cv::CMP_GT);
  keep_pieces_on_prior(p.keep_share);
  const cv::Rect box = support_of(mask_(reach_), support_) + reach_.tl();
  prior_(prior_box_).setTo(0);
  prior_box_ = cv::Rect();
  if (box.empty()) return;  // nothing kept: the start's own silhouette stands
  box_ = last_box_ = box;
  last_.setTo(0);
  mask_(box_).convertTo(last_(box_), CV_32F, 1.0 / 255);
  memory_.setTo(0);
  last_(box_).copyTo(memory_(box_));
  memory_box_ = box_;
  fullest_ = area_ = cv::sum(last_(box_))[0];
}

void FlowSegmenter::hold_in_place() {
  prior_(prior_box_).setTo(0);
  last_(last_box_).copyTo(prior_(last_box_));
  prior_box_ = last_box_;
  cv::compare(prior_, 0.5, inside_, cv::CMP_GT);
  split_ = MotionSplit{};
}

void FlowSegmenter::relearn_on(const WorkImages& img, const FlowModelParams& p) {
  relearn_ = false;
  const double area = cv::countNonZero(inside_(prior_box_));
  if (area < 1) return;
  const int ring = std::max(1, static_cast<int>(p.colour_ring * std::sqrt(area)));
  const cv::Rect near = square_ring(inside_, ring, ring_count_, around_);
  colours_.start(img.bgr(near), inside_(near));
  local_colours_.forget();
  if (outlined_ && p.local_colour_weight > 0)
    local_colours_.learn(img.bgr, near, inside_(near), around_, p.local_colour_cells);
}

void FlowSegmenter::resample(double rx, double ry, cv::Size size, int scale) {
  if (last_.empty()) return;
  const auto resized = [&](cv::Mat& m, int interpolation) {
    if (m.empty()) return;
    cv::Mat out;
    cv::resize(m, out, size, 0, 0, interpolation);
    m = out;
  };
  resized(mask_, cv::INTER_NEAREST);
  resized(last_, cv::INTER_LINEAR);
  resized(memory_, cv::INTER_LINEAR);
  prior_ = cv::Mat::zeros(size, CV_32F);
  prior_box_ = cv::Rect();
  box_ = last_box_ = support_of(last_, support_);
  memory_box_ = support_of(memory_, support_);
  if (box_.empty()) {
    forget(false);
    return;
  }
  area_ = cv::sum(last_(box_))[0];
  fullest_ *= rx * ry;
  split_.object.x *= static_cast<float>(rx), split_.object.y *= static_cast<float>(ry);
  split_.surroundings.x *= static_cast<float>(rx), split_.surroundings.y *= static_cast<float>(ry);
  split_.separation *= static_cast<float>(std::sqrt(rx * ry));
  local_colours_.rescale(rx, ry);
  flow_.resample(size);
  scale_ = scale;
}

void FlowSegmenter::forget(bool colours) {
  mask_.release();
  last_.release();
  memory_.release();
  prior_.release();
  box_ = last_box_ = memory_box_ = prior_box_ = cv::Rect();
  flow_.reset();
  local_colours_.forget();
  if (colours) colours_.forget();
}

bool FlowSegmenter::follow(const WorkImages& img, const FlowModelParams& p) {
  flow_level_ = level_for(p);
  if (last_.empty() || img.scale != scale_) {
    forget(false);
    return false;
  }
  // Across a new pixel format the last picture is no measure of this one's motion (its gray may
  // be another's): the silhouette stays where it was, and the colours are learned there anew.
  const bool measured =
      flow_.compute(img.gray, flow_level_, motion_needed(p, flow_level_), img.filled);
  if (relearn_) {
    hold_in_place();
  } else if (measured) {
    predict(p);
  } else {
    forget(false);
    return false;
  }
  const double area = cv::sum(prior_(prior_box_))[0];
  if (area < 1) {
    forget(false);
    return false;
  }
  if (relearn_) relearn_on(img, p);
  const int blur = static_cast<int>(p.prior_spread * std::sqrt(area)) | 1;
  reach_ = reach_of_prior(2 * blur);
  weigh_evidence(img, blur, p);
  // The last silhouette's box is the only part of mask_ not zero: cleared, not the whole.
  mask_(box_).setTo(0);
  cv::compare(log_odds_(reach_), 0, mask_(reach_), cv::CMP_GT);
  keep_pieces_on_prior(p.keep_share);
  evidence_ = evidence_within(mask_(reach_));
  box_ = support_of(mask_(reach_), support_) + reach_.tl();
  if (box_.empty()) {
    forget(false);
    return false;
  }
  return true;  // accept() or refuse() settles what the cut leaves
}

void FlowSegmenter::accept(const WorkImages& img, const FlowModelParams& p) {
  learn_colours(img, p);
  last_(last_box_).setTo(0);
  mask_(box_).convertTo(last_(box_), CV_32F, 1.0 / 255);
  last_box_ = box_;
  remember(p);
}

void FlowSegmenter::refuse() {
  // The cut refused is not the object; the last accepted silhouette carried along this frame's
  // motion (the prior's object) is, and nothing is learned of this frame.
  mask_(box_).setTo(0);
  cv::compare(prior_(prior_box_), 0.5, mask_(prior_box_), cv::CMP_GT);
  box_ = support_of(mask_(prior_box_), support_) + prior_box_.tl();
  if (box_.empty()) {
    forget(false);
    return;
  }
  last_(last_box_).setTo(0);
  mask_(box_).convertTo(last_(box_), CV_32F, 1.0 / 255);
  last_box_ = box_;
  area_ = cv::sum(last_(box_))[0];
}

namespace {

// Work units a work pixel of the part read costs: DIS at pyramid level 0, 1 and 2 (its patches
// are as many more as the level is finer, four times a level), and the rest of a frame's follow
// (carrying the prior, the evidence, the cut and its pieces, the learning). Measured against the
// estimators' units by tools/work_cost (docs/performance.md).
constexpr std::uint64_t kMotionCost[] = {120, 30, 8, 2, 1};
// The most pixels of its level a frame's motion is measured on: a part read that is wide for its
// object (a fast one, the remembered silhouette apart from it) is read a level coarser, so that
// no frame costs many times the usual (davis-dev's libby, a small dog running past poles, once
// read a part 40 times its area at full resolution).
constexpr int kMostFlowPixels = 1 << 15;
constexpr std::uint64_t kCutCost = 15;
// A start learns the colours of the whole work frame and keeps it for the next frame's motion.
constexpr std::uint64_t kStartCost = 12;

}  // namespace

std::uint64_t FlowSegmenter::follow_cost(const FlowModelParams& p) const {
  if (last_.empty()) return 0;
  const int level = level_for(p);
  return cost_at(motion_needed(p, level), level);
}

std::uint64_t FlowSegmenter::cost_at(const cv::Rect& part, int level) {
  const auto pixels = static_cast<std::uint64_t>(std::max(part.area(), 0));
  return pixels * (kMotionCost[std::clamp(level, 0, DenseFlow::kMaxLevel)] + kCutCost);
}

int FlowSegmenter::level_for(const FlowModelParams& p) const {
  int level = flow_level(area_, flow_level_, p.flow_span);
  while (level < DenseFlow::kMaxLevel &&
         ((motion_needed(p, level).area() >> (2 * level)) > kMostFlowPixels ||
          cost_at(motion_needed(p, level), level) > affordable_))
    ++level;
  return level;
}

std::uint64_t FlowSegmenter::start_cost(const WorkImages& img) {
  return kStartCost * static_cast<std::uint64_t>(img.size().area());
}

cv::Rect FlowSegmenter::motion_needed(const FlowModelParams& p, int level) const {
  const cv::Rect box = box_ | memory_box_;
  const double moved = split_.valid ? cv::norm(split_.object) : 0;
  return part_read(box, area_, moved, level, p, last_.size());
}

cv::Rect FlowSegmenter::part_read(const cv::Rect& box, double area, double moved, int level,
                                  const FlowModelParams& p, cv::Size size) {
  // Everything a frame reads of the flow lies within the last and the remembered silhouettes'
  // box grown by the prior's reach (two blurs) or the motion's ring, the wider, and by twice the
  // object's last motion (where it may have gone). One of DIS's patches more: without it, a small
  // object's flow at the region's edge was too poor (kite-surf's kiter lost).
  if (box.empty()) return box;
  const double across = std::sqrt(std::max(area, 1.0));
  const int patch = DenseFlow::kPatchSide << level;
  const int grow =
      static_cast<int>(std::max({2 * p.prior_spread, p.motion_ring, p.colour_ring}) * across +
                       2 * moved + 4 + patch);
  return grown_within(box, grow, size);
}

cv::Rect FlowSegmenter::images_needed(const FlowModelParams& p) const {
  // This frame's part read, and as far again as the object moved and a patch more: the next
  // frame's motion is measured against this one within it.
  const int level = level_for(p);
  const double moved = split_.valid ? cv::norm(split_.object) : 0;
  const int more = static_cast<int>(moved) + (DenseFlow::kPatchSide << level);
  return grown_within(motion_needed(p, level), more, last_.size());
}

cv::Rect FlowSegmenter::images_needed_at_start(const cv::Mat& inside, const FlowModelParams& p) {
  const cv::Rect box = cv::boundingRect(inside);
  const double area = cv::countNonZero(inside(box));
  const int level = flow_level(area, DenseFlow::kPresetLevel, p.flow_span);
  return grown_within(part_read(box, area, 0, level, p, inside.size()),
                      DenseFlow::kPatchSide << level, inside.size());
}

void FlowSegmenter::predict(const FlowModelParams& p) {
  // prior_ is zero but in the last prior's box.
  prior_(prior_box_).setTo(0);
  prior_box_ = carry_along_flow(last_, box_, flow_.backward(), flow_.measured(), map_, prior_);
  cv::compare(prior_, 0.5, inside_, cv::CMP_GT);
  split_ =
      split_motion(flow_.backward(), inside_, p.motion_ring, ring_count_, around_, motion_samples_);
  if (!split_.valid || p.memory_weight <= 0) return;
  // The backward flow says where the object came from: it moved by the opposite.
  // Only the memory's box, moved and grown by a pixel for the interpolation, is warped.
  const cv::Point2f by = -split_.object;
  const cv::Rect held = memory_box_;
  const cv::Rect to =
      cv::Rect(held.x + static_cast<int>(std::floor(by.x)) - 1,
               held.y + static_cast<int>(std::floor(by.y)) - 1, held.width + 3, held.height + 3) &
      cv::Rect(0, 0, memory_.cols, memory_.rows);
  if (!held.empty() && !to.empty()) {
    const cv::Matx23f move(1, 0, to.x - by.x, 0, 1, to.y - by.y);
    cv::warpAffine(memory_, moved_, move, to.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                   cv::BORDER_CONSTANT, 0);
  }
  memory_(held).setTo(0);
  memory_box_ = cv::Rect();
  if (held.empty() || to.empty()) return;
  moved_.copyTo(memory_(to));
  memory_box_ = support_of(moved_, support_) + to.tl();
  prior_box_ |= to;
  const auto weight = static_cast<float>(p.memory_weight);
  for (int y = to.y; y < to.y + to.height; ++y) {
    float* q = prior_.ptr<float>(y);
    const float* m = memory_.ptr<float>(y);
    for (int x = to.x; x < to.x + to.width; ++x) q[x] = std::max(q[x], weight * m[x]);
  }
}

cv::Rect FlowSegmenter::colour_ring(const FlowModelParams& p) {
  // The surroundings are the silhouette's square ring, as the motion's.
  const double area = cv::countNonZero(mask_(box_));
  const int r = std::max(1, static_cast<int>(p.colour_ring * std::sqrt(area)));
  return square_ring(mask_, r, ring_count_, around_);
}

void FlowSegmenter::learn_colours(const WorkImages& img, const FlowModelParams& p) {
  const cv::Rect near = colour_ring(p);
  colours_.learn(img.bgr(near), mask_(near), around_, p.learning_rate);
  if (local_colours_.learned())
    local_colours_.learn(img.bgr, near, mask_(near), around_, p.local_colour_cells);
}

void FlowSegmenter::remember(const FlowModelParams& p) {
  area_ = cv::sum(last_(box_))[0];
  fullest_ = std::max(fullest_ * (1 - p.memory_fade), area_);
  if (area_ < p.memory_refresh * fullest_) return;
  memory_(memory_box_).setTo(0);
  last_(box_).copyTo(memory_(box_));
  memory_box_ = box_;
}

cv::Rect FlowSegmenter::reach_of_prior(int blur) {
  // The object can be only where its prior reaches: a piece beyond it holds none of the prior and
  // is dropped, and one joined to the object grows at most a blur's width a frame.
  return grown_within(support_of(prior_(prior_box_), support_) + prior_box_.tl(), blur,
                      prior_.size());
}

void FlowSegmenter::weigh_evidence(const WorkImages& img, int blur, const FlowModelParams& p) {
  // The prior: the carried silhouette blurred as far as the object may have moved beyond the
  // flow, as log-odds; within the prior's reach only (the blur reads the pixels around it).
  log_odds_.create(prior_.size(), CV_32F);
  cv::Mat odds = log_odds_(reach_);
  if (blur > 1)
    cv::GaussianBlur(prior_(reach_), odds, {blur, blur}, 0);
  else
    prior_(reach_).copyTo(odds);
  prior_log_odds_.build(p.prior_floor);
  for (int y = 0; y < odds.rows; ++y) {
    float* l = odds.ptr<float>(y);
    for (int x = 0; x < odds.cols; ++x) l[x] = prior_log_odds_(l[x]);
  }
  odds.copyTo(prior_odds_);
  colours_.add_evidence(img.bgr(reach_), p.first_share, odds);
  // The cells moved with the object (the backward flow's opposite).
  local_colours_.add_evidence(img.bgr, reach_, split_.valid ? -split_.object : cv::Point2f(),
                              p.local_colour_weight, odds);
  if (split_.valid)
    add_motion_evidence(flow_.backward()(reach_), split_, p.motion_weight, p.min_separation, odds,
                        damp_new_pixels(img, p), p.new_motion_share);
}

const cv::Mat& FlowSegmenter::damp_new_pixels(const WorkImages& img, const FlowModelParams& p) {
  // Within the reach, the pixels outside the carried silhouette's core whose colour the first
  // frame's model calls the surroundings': a hand that moves with the object it holds. Only from
  // a point: an outlined start's local colours judge the new pixels near each part already.
  static const cv::Mat none;
  if (local_colours_.learned() || p.new_motion_share >= 1 || !colours_.learned()) return none;
  const int r = std::max(1, static_cast<int>(p.new_core * std::sqrt(std::max(area_, 1.0))));
  cv::erode(inside_(reach_), new_pixels_,
            cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  for (int y = 0; y < new_pixels_.rows; ++y) {
    std::uint8_t* n = new_pixels_.ptr<std::uint8_t>(y);
    const cv::Vec3b* c = img.bgr.ptr<cv::Vec3b>(reach_.y + y) + reach_.x;
    for (int x = 0; x < new_pixels_.cols; ++x)
      n[x] = !n[x] && colours_.first_ratio(c[x]) < 0 ? 255 : 0;
  }
  return new_pixels_;
}

double FlowSegmenter::evidence_within(const cv::Mat& mask) const {
  const cv::Mat total = log_odds_(reach_);
  double sum = 0;
  int n = 0;
  for (int y = 0; y < mask.rows; ++y) {
    const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
    const float* t = total.ptr<float>(y);
    const float* q = prior_odds_.ptr<float>(y);
    for (int x = 0; x < mask.cols; ++x)
      if (m[x]) sum += t[x] - q[x], ++n;
  }
  return n > 0 ? sum / n : 0;
}

void FlowSegmenter::keep_pieces_on_prior(double keep_share) {
  cv::Mat mask = mask_(reach_);
  const cv::Mat prior = prior_(reach_);
  const int n = cv::connectedComponents(mask, labels_, 8, CV_32S);
  if (n <= 2) return;  // the background and at most one piece
  held_.assign(n, 0.0);
  for (int y = 0; y < labels_.rows; ++y) {
    const int* l = labels_.ptr<int>(y);
    const float* q = prior.ptr<float>(y);
    for (int x = 0; x < labels_.cols; ++x) held_[l[x]] += q[x];
  }
  held_[0] = 0;
  const double least = keep_share * *std::max_element(held_.begin(), held_.end());
  for (int y = 0; y < labels_.rows; ++y) {
    const int* l = labels_.ptr<int>(y);
    std::uint8_t* m = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < labels_.cols; ++x)
      if (m[x] && !(held_[l[x]] > least)) m[x] = 0;
  }
}

}  // namespace projtrack
