#include "models/flow/flow_object_model.hpp"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/work_scale.hpp"

namespace projtrack {

template <>
std::unique_ptr<ObjectModel> make_object_model<ObjectModelKind::Flow>() {
  return std::make_unique<FlowObjectModel>();
}

namespace {

// The coarsest scale an object is followed at to fit the frame's budget.
constexpr int kMostScale = 8;

const WorkImages* work_images(FrameEvidence& ev) {
  const double pixels = static_cast<double>(ev.width()) * ev.height();
  return ev.images(work_scale(pixels, ev.tp.flow.work_pixels));
}

// `mask` (CV_8U, non-zero on the object) at `size`, 255 on the object: each pixel takes the
// object where more than half of what it covers is the object.
void resample_mask(const cv::Mat& mask, cv::Size size, cv::Mat& out) {
  if (mask.size() == size) {
    cv::compare(mask, 0, out, cv::CMP_GT);
    return;
  }
  cv::Mat binary = mask > 0, resized;
  const bool shrinks = size.width <= mask.cols;
  cv::resize(binary, resized, size, 0, 0, shrinks ? cv::INTER_AREA : cv::INTER_LINEAR);
  cv::compare(resized, 127, out, cv::CMP_GT);
}

// The scale at which an object of `area` frame px holds about `object_pixels` work px.
int object_scale(double area, double object_pixels) {
  if (!(area > 0) || !(object_pixels > 0)) return 1;
  return std::max(1, static_cast<int>(std::lround(std::sqrt(area / object_pixels))));
}

// Takes `units` from the frame's budget; false, taking nothing, when they do not fit (or the
// stop flag is set).
bool pay(WorkBudget& budget, std::uint64_t units) {
  if (budget.exhausted(units)) return false;
  budget.spend(units);
  return true;
}

}  // namespace

Observation FlowObjectModel::observed(bool resumed) {
  const cv::Mat& m = segmenter_.silhouette();
  const cv::Rect& b = segmenter_.silhouette_box();
  silhouette_.reset({b.x, b.y, b.width, b.height});
  for (int y = 0; y < b.height; ++y) {
    const std::uint8_t* from = m.ptr<std::uint8_t>(b.y + y) + b.x;
    std::uint8_t* to = silhouette_.row(y);
    for (int x = 0; x < b.width; ++x) to[x] = from[x] ? 1 : 0;
  }
  return Observation::of_silhouette(silhouette_, segmenter_.scale(), resumed);
}

Observation FlowObjectModel::start(FrameEvidence& ev, const StartRequest& request,
                                   const Track& track) {
  // The first silhouette is found on the whole frame at its working scale; the object is then
  // followed at its own scale (FlowModelParams::object_pixels).
  const WorkImages* whole = work_images(ev);
  if (!whole || !pay(ev.budget, FlowSegmenter::start_cost(*whole))) return Observation::stopped();
  // A mask or a box bounds the first silhouette; a point does not.
  const bool outlined =
      request.from == StartRequest::From::Mask || request.from == StartRequest::From::Box;
  const FirstSilhouette start = first_silhouette(ev, request, track, *whole);
  if (!start.found) {
    if (ev.budget.ran_out() || ev.budget.interrupted()) return Observation::stopped();
    return Observation::missing(start.why);
  }
  return begin(ev, *whole, request.from == StartRequest::From::Mask ? request.mask : nullptr,
               outlined, start.resumed);
}

Observation FlowObjectModel::begin(FrameEvidence& ev, const WorkImages& whole, const cv::Mat* mask,
                                   bool outlined, bool resumed) {
  const double area =
      mask ? cv::countNonZero(*mask)
           : cv::countNonZero(inside_) * static_cast<double>(whole.scale) * whole.scale;
  object_pixels_ = ev.tp.flow.object_pixels;
  scale_ = object_scale(area, object_pixels_);
  resample_mask(mask ? *mask : inside_, work_size(ev.width(), ev.height(), scale_), object_inside_);
  if (cv::countNonZero(object_inside_) == 0)
    return Observation::missing("the first silhouette covers no pixel at the object's scale");
  const WorkImages* img =
      ev.images(scale_, FlowSegmenter::images_needed_at_start(object_inside_, ev.tp.flow));
  if (!img) return Observation::stopped();
  segmenter_.start(whole, inside_, *img, object_inside_, ev.tp.flow, outlined, mask == nullptr);
  starting_ = true;
  return observed(resumed);
}

Observation FlowObjectModel::follow(FrameEvidence& ev, const Track& track) {
  starting_ = false;
  if (refind_) {
    refind_ = false;
    Observation o;
    if (found_again(ev, track, o)) return o;
  }
  // A tenth of what is left stays for the estimate on the silhouette.
  const std::uint64_t affordable = ev.budget.left() - ev.budget.left() / 10;
  // A coarser flow level first (the cheaper loss), then a coarser scale.
  segmenter_.afford(affordable);
  follow_scale(ev, affordable);
  const WorkImages* img = ev.images(scale_, segmenter_.images_needed(ev.tp.flow));
  if (img && segmenter_.follow_cost(ev.tp.flow) > ev.budget.left() && scale_ < kMostScale) {
    // The estimate fell short: once more a scale coarser (its work images are cheaper still).
    follow_at(ev, scale_ + 1);
    segmenter_.afford(ev.budget.left());
    img = ev.images(scale_, segmenter_.images_needed(ev.tp.flow));
  }
  if (!img || !pay(ev.budget, segmenter_.follow_cost(ev.tp.flow))) return Observation::stopped();
  if (!segmenter_.follow(*img, ev.tp.flow))
    return Observation::missing(
        "nothing of the object is left where the picture's motion carried it");
  followed_ = img;
  followed_params_ = &ev.tp.flow;
  return observed(false);
}

bool FlowObjectModel::found_again(FrameEvidence& ev, const Track& track, Observation& o) {
  const WorkImages* whole = work_images(ev);
  if (!whole || !find_again(ev, track, *whole).found) return false;
  o = begin(ev, *whole, nullptr, false, false);
  starting_ = false;  // the same track goes on: judged and learned from as any followed frame
  usual_support_ = 0;
  return o.kind == Observation::Kind::Silhouette;
}

void FlowObjectModel::follow_scale(const FrameEvidence& ev, std::uint64_t affordable) {
  // An object that grew or shrank to half or twice its area at its scale is followed at the scale
  // its size asks for now (hysteresis: no switch back and forth for an object near the limit).
  object_pixels_ = ev.tp.flow.object_pixels;
  const double area = segmenter_.area() * scale_ * scale_;
  int scale = object_scale(area, object_pixels_);
  const double ratio = static_cast<double>(scale) / scale_;
  if (ratio * ratio < 2 && ratio * ratio > 0.5) scale = scale_;
  // A coarser one while the budget cannot pay for this one's follow (several objects share a
  // frame's budget): a follow costs as many times less as it reads fewer work pixels.
  const double cost = static_cast<double>(segmenter_.follow_cost(ev.tp.flow));
  while (scale < kMostScale &&
         cost * scale_ * scale_ > static_cast<double>(affordable) * scale * scale)
    ++scale;
  follow_at(ev, scale);
}

void FlowObjectModel::follow_at(const FrameEvidence& ev, int scale) {
  if (scale == scale_) return;
  const double r = static_cast<double>(scale_) / scale;
  segmenter_.resample(r, r, work_size(ev.width(), ev.height(), scale), scale);
  scale_ = scale;
}

Veto FlowObjectModel::veto(FrameEvidence&, const Features&, const Track&) {
  // The silhouette carried where the motion says, but this frame's colours and motion do not say
  // "object" there as they did: a blank frame, a covered lens, a cut to another shot. Judged
  // against the track's own usual evidence (objects differ by tens of nats in how far their
  // colours stand apart).
  if (starting_ || !(usual_support_ > 0)) return {};
  const double support = segmenter_.evidence_support();
  if (support >= kLeastSupport * usual_support_) return {};
  char why[160];
  std::snprintf(why, sizeof why,
                "this frame shows little of the object where it was carried: its colours and "
                "motion say %.2g nats against the track's usual %.2g",
                support, usual_support_);
  return {why, false};
}

void FlowObjectModel::settle(Verdict verdict) {
  // A followed frame is learned from and carried on only when its estimate was accepted.
  if (followed_) {
    if (verdict == Verdict::Accepted)
      segmenter_.accept(*followed_, *followed_params_);
    else
      segmenter_.refuse();
    followed_ = nullptr;
    followed_params_ = nullptr;
  }
  // A start not taken leaves nothing to follow.
  if (starting_ && verdict != Verdict::Accepted) segmenter_.forget(false);
  if (starting_ && verdict == Verdict::Accepted) {
    usual_support_ = 0;
    largest_area_ = 0;
    searched_ = 0;
    moving_.reset();  // its frames are of before this track: a later search starts afresh
    last_searched_.release();
  }
  if (verdict == Verdict::Accepted)
    largest_area_ = std::max(largest_area_, segmenter_.area() * scale_ * scale_);
  if (!starting_ && verdict == Verdict::Accepted) {
    const double support = segmenter_.evidence_support();
    usual_support_ =
        usual_support_ > 0 ? (1 - kSupportRate) * usual_support_ + kSupportRate * support : support;
  }
  starting_ = false;
}

bool FlowObjectModel::rescale(double sx, double sy, int width, int height) {
  // The silhouette and the last picture follow the frame to its new size, at the scale the
  // object's new size asks for; the colours stay (a resize changes none).
  if (!segmenter_.tracking()) return false;
  const double area = segmenter_.area() * scale_ * scale_ * sx * sy;
  const int scale = object_scale(area, object_pixels_);
  segmenter_.resample(sx * scale_ / scale, sy * scale_ / scale, work_size(width, height, scale),
                      scale);
  scale_ = scale;
  // The picture may have been cut with the size (a clip joined to another): on the next frame
  // the object is looked for by its colours near where it was, before it is followed on.
  refind_ = true;
  return segmenter_.tracking();
}

bool FlowObjectModel::relearn() {
  // The silhouette stays where it is; its colours and its surroundings' are learned anew on the
  // next frame, where the motion carries it (the element's caps, Python's frames: colour to gray).
  usual_support_ = 0;
  if (!segmenter_.tracking()) return false;
  segmenter_.relearn_colours();
  return true;
}

void FlowObjectModel::forget(Forget what) {
  // A track dropped keeps the object's colours to find it again (Forget::Position).
  segmenter_.forget(what == Forget::Everything);
  followed_ = nullptr;
  followed_params_ = nullptr;
  moving_.reset();
  last_searched_.release();
  searched_ = 0;
  usual_support_ = 0;
  if (what == Forget::Everything) largest_area_ = 0;
}

SilhouetteMask FlowObjectModel::silhouette(int frame_width, int frame_height) const {
  const cv::Mat& m = segmenter_.silhouette();
  const cv::Rect& b = segmenter_.silhouette_box();
  if (m.empty() || b.empty()) return {};
  return {ImageView(m.ptr(b.y) + b.x, b.width, b.height, static_cast<std::ptrdiff_t>(m.step)),
          Rect{b.x, b.y, b.width, b.height}, segmenter_.scale(), frame_width, frame_height};
}

double FlowObjectModel::explains(const FramePixels& pixels) const {
  // Only a followed frame weighed its own evidence (a start has none of this frame's).
  return followed_ ? segmenter_.evidence_over(pixels) : -HUGE_VAL;
}

Observation FlowObjectModel::give_up(const FramePixels& pixels, const Observation& o) {
  if (!segmenter_.give_up(pixels)) return Observation::missing("hidden by another object");
  Observation left = observed(o.resumed);
  left.area_limit = o.area_limit;
  return left;
}

}  // namespace projtrack
