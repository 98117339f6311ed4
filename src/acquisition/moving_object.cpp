#include "acquisition/moving_object.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

constexpr int kRing = MovingObjectFinder::kLongBaseline + 1;

// Work units (≈ ns, WorkBudget's unit) per pixel of the image each stage reads, from each stage
// timed alone on opencv-doc's cup clip at 640×480 and 1920×1080 input (working frames 365×274
// and 422×237), one thread, on the shared development machine (load 3–5 on 2 cores): loading
// 15–28 µs (the working frame's pixels, vectorised: kScannedPixelsPerCost a unit), the flow
// 0.9–1.2 ms (DIS: 6.2k quarter pixels), the evidence 420–530 µs and the regions 160–220 µs
// (25k half pixels each), the silhouette 80–125 µs (mostly its upscaling to the working frame).
constexpr std::uint64_t kFlowPerQuarterPixel = 160;  // DIS ultrafast at its finest level + the fit
constexpr std::uint64_t kEvidencePerHalfPixel = 19;  // two warps, differences, means, histograms
constexpr std::uint64_t kRegionsPerHalfPixel = 8;    // box sums, labels, the regions' scans
constexpr std::uint64_t kSilhouettePerBoxPixel = 8;  // closing, holes (the region's box)

// DIS refuses images smaller than its patch pyramid; below this side the motion is not measured
// (the picture is taken as still).
constexpr int kLeastFlowSide = 16;

// `why` = the formatted text, in the string's own buffer (no temporaries: nothing allocated once
// it has grown).
template <class... Args>
void say(std::string& why, const char* format, Args... args) {
  char text[128];
  std::snprintf(text, sizeof text, format, args...);
  why.assign(text);
}

// The median of `v` (reordered).
float median_of(std::vector<float>& v) {
  if (v.empty()) return 0.f;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Sums of `src` (CV_8U) over the (2r+1)² window around each pixel, clipped to the image, into
// `out` (CV_16U, same size; `rows` and `acc` its scratch): separable running sums, so the cost is
// the pixels' and not the window's. `src` and `out` may be views into larger images.
void box_sum(const cv::Mat& src, int r, cv::Mat& rows, std::vector<int>& acc, cv::Mat& out) {
  const int w = src.cols, h = src.rows;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* s = src.ptr<std::uint8_t>(y);
    std::uint16_t* d = rows.ptr<std::uint16_t>(y);
    int acc = 0;
    for (int x = 0; x <= std::min(r, w - 1); ++x) acc += s[x];
    for (int x = 0; x < w; ++x) {
      d[x] = static_cast<std::uint16_t>(acc);
      if (x + r + 1 < w) acc += s[x + r + 1];
      if (x - r >= 0) acc -= s[x - r];
    }
  }
  // Down the columns, a row at a time (in the order rows lie in memory).
  acc.assign(static_cast<std::size_t>(w), 0);
  for (int y = 0; y <= std::min(r, h - 1); ++y) {
    const std::uint16_t* in = rows.ptr<std::uint16_t>(y);
    for (int x = 0; x < w; ++x) acc[x] += in[x];
  }
  for (int y = 0; y < h; ++y) {
    std::uint16_t* o = out.ptr<std::uint16_t>(y);
    for (int x = 0; x < w; ++x) o[x] = static_cast<std::uint16_t>(acc[x]);
    if (y + r + 1 < h) {
      const std::uint16_t* in = rows.ptr<std::uint16_t>(y + r + 1);
      for (int x = 0; x < w; ++x) acc[x] += in[x];
    }
    if (y - r >= 0) {
      const std::uint16_t* in = rows.ptr<std::uint16_t>(y - r);
      for (int x = 0; x < w; ++x) acc[x] -= in[x];
    }
  }
}

// The 3×3 mean of |a − b| (CV_8U), rounded, into `out`.
void mean_difference(const cv::Mat& a, const cv::Mat& b, cv::Mat& diff, cv::Mat& rows,
                     std::vector<int>& acc, cv::Mat& sums, cv::Mat& out) {
  cv::absdiff(a, b, diff);
  box_sum(diff, 1, rows, acc, sums);
  for (int y = 0; y < out.rows; ++y) {
    const std::uint16_t* s = sums.ptr<std::uint16_t>(y);
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < out.cols; ++x) o[x] = static_cast<std::uint8_t>((s[x] + 4) / 9);
  }
}

// `src` warped by the similarity x' = [a −b; b a]·x + t into `dst` (dst(x) = src(x'),
// bilinear with 8-bit weights, the border repeated): cv::warpAffine made 43 heap allocations a
// call here (its remap tables, even on one thread), this loop none. Coordinates step in 16.16
// fixed point along a row.
void warp_similarity(const cv::Mat& src, double a, double b, double tx, double ty, cv::Mat& dst) {
  const int w = src.cols, h = src.rows;
  constexpr double kOne = 65536.0;
  const auto step_x = static_cast<std::int64_t>(std::llround(a * kOne));
  const auto step_y = static_cast<std::int64_t>(std::llround(b * kOne));
  for (int y = 0; y < dst.rows; ++y) {
    std::uint8_t* out = dst.ptr<std::uint8_t>(y);
    std::int64_t sx = std::llround((-b * y + tx) * kOne), sy = std::llround((a * y + ty) * kOne);
    for (int x = 0; x < dst.cols; ++x, sx += step_x, sy += step_y) {
      std::int64_t cx = sx, cy = sy;
      if (cx < 0 || cy < 0 || cx >= (std::int64_t(w - 1) << 16) ||
          cy >= (std::int64_t(h - 1) << 16)) {
        cx = std::clamp<std::int64_t>(cx, 0, std::int64_t(w - 1) << 16);
        cy = std::clamp<std::int64_t>(cy, 0, std::int64_t(h - 1) << 16);
      }
      const int x0 = static_cast<int>(cx >> 16), y0 = static_cast<int>(cy >> 16);
      const int fx = static_cast<int>((cx >> 8) & 255), fy = static_cast<int>((cy >> 8) & 255);
      const int x1 = std::min(x0 + 1, w - 1);
      const std::uint8_t* r0 = src.ptr<std::uint8_t>(y0);
      const std::uint8_t* r1 = src.ptr<std::uint8_t>(std::min(y0 + 1, h - 1));
      const int top = r0[x0] * (256 - fx) + r0[x1] * fx;
      const int bottom = r1[x0] * (256 - fx) + r1[x1] * fx;
      out[x] = static_cast<std::uint8_t>((top * (256 - fy) + bottom * fy + (1 << 15)) >> 16);
    }
  }
}

// z of (b − a) × (c − a): > 0 when a, b, c turn one way.
long cross(const cv::Point& a, const cv::Point& b, const cv::Point& c) {
  return static_cast<long>(b.x - a.x) * (c.y - a.y) - static_cast<long>(b.y - a.y) * (c.x - a.x);
}

// The convex hull of `points` sorted by (y, x) (Andrew's monotone chain), into `hull`, which
// keeps its capacity (cv::convexHull allocates a call).
void monotone_hull(const std::vector<cv::Point>& points, std::vector<cv::Point>& hull) {
  hull.resize(2 * points.size());
  std::size_t k = 0;
  for (const cv::Point& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k > 1 ? k - 1 : k);  // the last point is the first
}

// Sets to 1 the pixels of `mask` within the convex polygon `hull` (its vertices pixel centres),
// row by row from its edges' crossings.
void fill_convex(const std::vector<cv::Point>& hull, cv::Mat& mask) {
  int top = mask.rows, bottom = -1;
  for (const cv::Point& p : hull) top = std::min(top, p.y), bottom = std::max(bottom, p.y);
  for (int y = std::max(top, 0); y <= std::min(bottom, mask.rows - 1); ++y) {
    double left = mask.cols, right = -1;
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const cv::Point& p = hull[i];
      const cv::Point& q = hull[(i + 1) % hull.size()];
      if (y < std::min(p.y, q.y) || y > std::max(p.y, q.y)) continue;
      const double x0 = p.y == q.y ? p.x : p.x + double(y - p.y) * (q.x - p.x) / (q.y - p.y);
      const double x1 = p.y == q.y ? q.x : x0;
      left = std::min({left, x0, x1});
      right = std::max({right, x0, x1});
    }
    std::uint8_t* m = mask.ptr<std::uint8_t>(y);
    const int from = std::max(0, static_cast<int>(std::lround(left)));
    const int to = std::min(mask.cols - 1, static_cast<int>(std::lround(right)));
    for (int x = from; x <= to; ++x) m[x] = 1;
  }
}

// `inner` ∘ then `outer`: the similarity that applies `inner` first.
template <class M>
M compose(const M& outer, const M& inner) {
  M c;
  c.a = outer.a * inner.a - outer.b * inner.b;
  c.b = outer.a * inner.b + outer.b * inner.a;
  c.tx = outer.a * inner.tx - outer.b * inner.ty + outer.tx;
  c.ty = outer.b * inner.tx + outer.a * inner.ty + outer.ty;
  return c;
}

}  // namespace

void MovingObjectFinder::reset() {
  size_ = cv::Size();
  newest_ = -1;
  frames_seen_ = 0;
  dis_.release();
  last_quarter_.release();
  last_threshold_ = -1;
  regions_.clear();
  last_regions_.clear();
}

void MovingObjectFinder::forget_history() {
  frames_seen_ = std::min(frames_seen_, 1);
  last_regions_.clear();
}

bool MovingObjectFinder::find(const cv::Mat& gray, WorkBudget& budget, cv::Mat& silhouette,
                              std::string& why) {
  if (budget.exhausted()) {
    why = budget.interrupted() ? "stopped" : "out of work budget";
    return false;
  }
  if (gray.empty() || gray.type() != CV_8UC1) {
    why = "no frame (a CV_8U gray image is needed)";
    return false;
  }
  if (!load(gray, budget, why)) return false;
  if (budget.exhausted()) {
    last_regions_.clear();  // this frame was not looked at: no run goes on through it
    why = budget.interrupted() ? "stopped" : "out of work budget";
    return false;
  }
  if (flat_) {
    // A uniform picture holds no object (and costs no more than its loading).
    last_regions_.clear();
    why = "a flat frame: nothing in it to find";
    return false;
  }
  const bool compared = frames_seen_ >= 3;  // else nothing to compare with yet
  const bool marked = mark_evidence(why);
  if (compared) budget.spend(kEvidencePerHalfPixel * half_size_.area());
  if (!marked) return false;
  if (budget.exhausted()) {
    last_regions_.clear();
    why = budget.interrupted() ? "stopped" : "out of work budget";
    return false;
  }
  group_evidence();
  measure_regions();
  continue_runs();
  budget.spend(kRegionsPerHalfPixel * half_size_.area());
  const Region* best = nullptr;
  for (const Region& r : regions_)
    if (r.streak >= params_.frames && (!best || r.streak > best->streak ||
                                       (r.streak == best->streak && r.evidence > best->evidence)))
      best = &r;
  if (!best) {
    int longest = 0;
    for (const Region& r : regions_) longest = std::max(longest, r.streak);
    if (regions_.empty())
      why = "no compact region wholly in view moves apart from the picture";
    else
      say(why, "a region moves apart, seen on %d of %d frames in a row", longest, params_.frames);
    return false;
  }
  draw_silhouette(*best, silhouette);
  budget.spend(kSilhouettePerBoxPixel * static_cast<std::uint64_t>(boxes_[best->label].area()) +
               static_cast<std::uint64_t>(size_.area()) / kScannedPixelsPerCost);
  say(why, "an object moving apart from the picture, seen on %d frames in a row", best->streak);
  return true;
}

bool MovingObjectFinder::load(const cv::Mat& gray, WorkBudget& budget, std::string& why) {
  if (gray.size() != size_) {
    reset();
    size_ = gray.size();
    // Halved exactly (an even crop: the motion's scale between the levels is exactly 2).
    half_size_ = cv::Size(size_.width / 2, size_.height / 2);
    radius_ =
        std::max(1, static_cast<int>(std::lround(params_.group_share *
                                                 std::hypot(half_size_.width, half_size_.height))));
    for (cv::Mat& m : halves_) m.create(half_size_, CV_8U);
    for (cv::Mat* m : {&warped_, &warped_short_, &diff_short_, &diff_long_, &marks_, &grouped_,
                       &closed_, &filled_, &half_silhouette_})
      m->create(half_size_, CV_8U);
    sums_.create(half_size_, CV_16U);
    row_sums_.create(half_size_, CV_16U);
  }
  if (half_size_.width < 2 || half_size_.height < 2) {
    why = "a frame too small to look for motion in";
    return false;
  }
  newest_ = (newest_ + 1) % kRing;
  cv::resize(gray(cv::Rect(0, 0, 2 * half_size_.width, 2 * half_size_.height)), halves_[newest_],
             half_size_, 0, 0, cv::INTER_AREA);
  const cv::Size quarter(half_size_.width / 2, half_size_.height / 2);
  cv::resize(halves_[newest_](cv::Rect(0, 0, 2 * quarter.width, 2 * quarter.height)), quarter_,
             quarter, 0, 0, cv::INTER_AREA);
  budget.spend(static_cast<std::uint64_t>(size_.area()) / kScannedPixelsPerCost);
  frames_seen_ = std::min(frames_seen_ + 1, kRing);
  motions_[newest_] = Motion();
  double lo = 0, hi = 0;
  cv::minMaxLoc(quarter_, &lo, &hi);
  flat_ = hi - lo <= 2;  // within the rounding of the halvings
  if (frames_seen_ > 1 && !measure_motion(budget)) forget_history();
  cv::swap(quarter_, last_quarter_);
  return true;
}

bool MovingObjectFinder::measure_motion(WorkBudget& budget) {
  const cv::Mat& now = quarter_;
  if (std::min(now.cols, now.rows) < kLeastFlowSide) return true;  // taken as still
  if (flat_) return true;  // no motion to measure: the picture is taken as still
  if (!dis_) {
    dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
    dis_->setFinestScale(0);  // the quarter frame is the preset's own level 2
  }
  try {
    dis_->calc(now, last_quarter_, flow_);
  } catch (const cv::Exception&) {
    dis_.release();
    return false;
  }
  budget.spend(kFlowPerQuarterPixel * static_cast<std::uint64_t>(now.total()));
  Motion q;
  fit_motion(q);
  // From quarter to half pixels: x_h = 2·x_q + 1/2.
  Motion& h = motions_[newest_];
  h.a = q.a;
  h.b = q.b;
  h.tx = 2 * q.tx + 0.5 - 0.5 * (q.a - q.b);
  h.ty = 2 * q.ty + 0.5 - 0.5 * (q.a + q.b);
  return true;
}

// The picture's motion fitted to the flow: the median shift, then twice least squares on the
// vectors within three robust spreads of the last fit (the moving object's are left out as long
// as it covers under half of the frame; no fixed tolerance in pixels).
void MovingObjectFinder::fit_motion(Motion& m) {
  dx_.clear();
  dy_.clear();
  sample_x_.clear();
  sample_y_.clear();
  for (int y = 0; y < flow_.rows; y += 2) {
    const cv::Vec2f* f = flow_.ptr<cv::Vec2f>(y);
    for (int x = 0; x < flow_.cols; x += 2) {
      dx_.push_back(f[x][0]);
      dy_.push_back(f[x][1]);
      sample_x_.push_back(x);
      sample_y_.push_back(y);
    }
  }
  scratch_ = dx_;
  m = Motion();
  m.tx = median_of(scratch_);
  scratch_ = dy_;
  m.ty = median_of(scratch_);
  for (int pass = 0; pass < 2; ++pass) {
    const double tolerance = 3 * residual_spread(m);
    double sx = 0, sy = 0, qx = 0, qy = 0, n = 0;
    double spp = 0, spq = 0, scross = 0;
    const Motion fit = m;
    for (std::size_t i = 0; i < dx_.size(); ++i) {
      const double px = sample_x_[i], py = sample_y_[i];
      const double tx = px + dx_[i], ty = py + dy_[i];
      const double ex = fit.a * px - fit.b * py + fit.tx - tx;
      const double ey = fit.b * px + fit.a * py + fit.ty - ty;
      if (ex * ex + ey * ey > tolerance * tolerance) continue;
      sx += px, sy += py, qx += tx, qy += ty, n += 1;
      spp += px * px + py * py, spq += px * tx + py * ty, scross += px * ty - py * tx;
    }
    if (n < 3) return;
    const double mx = sx / n, my = sy / n, nx = qx / n, ny = qy / n;
    const double var = spp - n * (mx * mx + my * my);
    if (var <= 1e-9) return;
    m.a = (spq - n * (mx * nx + my * ny)) / var;
    m.b = (scross - n * (mx * ny - my * nx)) / var;
    m.tx = nx - (m.a * mx - m.b * my);
    m.ty = ny - (m.b * mx + m.a * my);
  }
}

// 1.4826 × the median distance of the flow's vectors from `m`'s (at least a hundredth of a
// pixel: a synthetic still picture's flow is exact).
double MovingObjectFinder::residual_spread(const Motion& m) {
  scratch_.resize(dx_.size());
  for (std::size_t i = 0; i < dx_.size(); ++i) {
    const double px = sample_x_[i], py = sample_y_[i];
    const double ex = m.a * px - m.b * py + m.tx - (px + dx_[i]);
    const double ey = m.b * px + m.a * py + m.ty - (py + dy_[i]);
    scratch_[i] = static_cast<float>(std::sqrt(ex * ex + ey * ey));
  }
  return std::max(0.01, 1.4826 * median_of(scratch_));
}

// The 3×3 mean difference between this frame and the one `baseline` frames back, warped onto
// this one by the motions in between.
void MovingObjectFinder::evidence(int baseline, cv::Mat& warped, cv::Mat& diff) {
  Motion to_then;  // this frame's pixels onto the frame `baseline` back
  for (int k = 0; k < baseline; ++k)
    to_then = compose(motions_[(newest_ - k + kRing) % kRing], to_then);
  const cv::Mat& then = halves_[(newest_ - baseline + kRing) % kRing];
  warp_similarity(then, to_then.a, to_then.b, to_then.tx, to_then.ty, warped);
  mean_difference(halves_[newest_], warped, closed_, row_sums_, column_sums_, sums_, diff);
}

// A difference's threshold: its median + noise_spreads robust spreads (1.4826 × MAD, at least
// half a grey level: the rounding of the mean), from its histogram.
double MovingObjectFinder::threshold(const cv::Mat& diff) const {
  std::array<int, 256> hist{};
  for (int y = 0; y < diff.rows; ++y) {
    const std::uint8_t* d = diff.ptr<std::uint8_t>(y);
    for (int x = 0; x < diff.cols; ++x) ++hist[d[x]];
  }
  const int half = static_cast<int>(diff.total() / 2);
  int median = 0;
  for (int seen = 0; median < 255 && (seen += hist[median]) <= half;) ++median;
  std::array<int, 256> spread{};
  for (int v = 0; v < 256; ++v) spread[std::abs(v - median)] += hist[v];
  int mad = 0;
  for (int seen = 0; mad < 255 && (seen += spread[mad]) <= half;) ++mad;
  return median + params_.noise_spreads * std::max(1.4826 * mad, 0.5);
}

// The pixels whose change both baselines show (marks_, 0/1); false when the frame cannot tell
// (too few frames yet, a change of the whole picture).
bool MovingObjectFinder::mark_evidence(std::string& why) {
  if (frames_seen_ < 3) {
    say(why, "too few frames yet to tell motion (%d of 3)", frames_seen_);
    return false;
  }
  const int long_baseline = std::min(kLongBaseline, frames_seen_ - 1);
  evidence(1, warped_short_, diff_short_);
  evidence(long_baseline, warped_, diff_long_);
  const double t_short = threshold(diff_short_), t_long = threshold(diff_long_);
  short_threshold_ = t_short;
  const double calm = last_threshold_ >= 0 ? last_threshold_ : t_short;
  std::size_t marked = 0, changed = 0;
  for (int y = 0; y < half_size_.height; ++y) {
    const std::uint8_t* s = diff_short_.ptr<std::uint8_t>(y);
    const std::uint8_t* l = diff_long_.ptr<std::uint8_t>(y);
    std::uint8_t* m = marks_.ptr<std::uint8_t>(y);
    for (int x = 0; x < half_size_.width; ++x) {
      m[x] = s[x] > t_short && l[x] > t_long;
      marked += m[x];
      changed += s[x] > calm;
    }
  }
  // A change over most of the picture against the last calm frame (a flash, a cut, noise
  // everywhere): no object, and the frames before it are no reference.
  const double most = params_.global_share * static_cast<double>(half_size_.area());
  if (static_cast<double>(changed) > most || static_cast<double>(marked) > most) {
    forget_history();
    why = "a change over the whole picture (a flash, a cut, noise): no object in it";
    return false;
  }
  last_threshold_ = t_short;
  return true;
}

// Drops the sparse specks from marks_, then groups what is left: grouped_ is marks_ grown by
// the grouping radius, labelled into labels_.
void MovingObjectFinder::group_evidence() {
  const int side = 2 * radius_ + 1;
  const int least = static_cast<int>(std::ceil(params_.least_density * side * side));
  box_sum(marks_, radius_, row_sums_, column_sums_, sums_);
  for (int y = 0; y < half_size_.height; ++y) {
    const std::uint16_t* s = sums_.ptr<std::uint16_t>(y);
    std::uint8_t* m = marks_.ptr<std::uint8_t>(y);
    for (int x = 0; x < half_size_.width; ++x) m[x] = m[x] && s[x] >= least;
  }
  box_sum(marks_, radius_, row_sums_, column_sums_, sums_);
  for (int y = 0; y < half_size_.height; ++y) {
    const std::uint16_t* s = sums_.ptr<std::uint16_t>(y);
    std::uint8_t* g = grouped_.ptr<std::uint8_t>(y);
    for (int x = 0; x < half_size_.width; ++x) g[x] = s[x] > 0;
  }
  labels_.label(ImageView(grouped_.data, grouped_.cols, grouped_.rows, grouped_.step), false);
}

// Each group's evidence: its box and count, then, for groups clear of the frame's border, its
// hull, kept as a region when compact and of a plausible size.
void MovingObjectFinder::measure_regions() {
  const int n = labels_.count();
  boxes_.assign(static_cast<std::size_t>(n) + 1, cv::Rect());
  counts_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int y = 0; y < half_size_.height; ++y) {
    const std::uint8_t* m = marks_.ptr<std::uint8_t>(y);
    const std::int32_t* l = labels_.row(y);
    for (int x = 0; x < half_size_.width; ++x) {
      if (!m[x]) continue;
      cv::Rect& b = boxes_[l[x]];
      b = counts_[l[x]]++ ? (b | cv::Rect(x, y, 1, 1)) : cv::Rect(x, y, 1, 1);
    }
  }
  regions_.clear();
  const double frame = half_size_.area();
  for (int label = 1; label <= n; ++label) {
    const cv::Rect& b = boxes_[label];
    if (counts_[label] < 3) continue;
    // Wholly in view: an arm reaching in, a region cut by the frame's edge, is no object to take.
    if (b.x == 0 || b.y == 0 || b.br().x == half_size_.width || b.br().y == half_size_.height)
      continue;
    if (b.area() < params_.least_share * frame || !hull_of(label, b)) continue;
    const double perimeter = cv::arcLength(hull_, true);
    const double area = cv::contourArea(hull_) + 0.5 * perimeter + 1;  // pixels, not centres
    const double compactness = 4 * CV_PI * area / std::max(1.0, perimeter * perimeter);
    if (area < params_.least_share * frame || area > params_.most_share * frame ||
        compactness < params_.least_compactness)
      continue;
    if (lit_not_moved(b)) continue;
    const cv::Moments mo = cv::moments(hull_);
    Region r;
    r.centre = mo.m00 > 0 ? cv::Point2d(mo.m10 / mo.m00, mo.m01 / mo.m00)
                          : cv::Point2d(b.x + 0.5 * b.width, b.y + 0.5 * b.height);
    r.area = area;
    r.evidence = counts_[label];
    r.label = label;
    regions_.push_back(r);
  }
}

// Whether the change in `box` (a region's evidence) is a change of light rather than a motion:
// this frame there is the last one (warped) times a gain plus an offset, least squares, to
// within the short difference's threshold at most of the region's evidence pixels (a shadow
// passing, a lamp, a screen). A motion moves some pixels up and others down, which no gain
// explains.
bool MovingObjectFinder::lit_not_moved(const cv::Rect& box) const {
  double n = 0, sw = 0, sh = 0, sww = 0, swh = 0;
  for (int y = box.y; y < box.br().y; ++y) {
    const std::uint8_t* h = halves_[newest_].ptr<std::uint8_t>(y);
    const std::uint8_t* w = warped_short_.ptr<std::uint8_t>(y);
    for (int x = box.x; x < box.br().x; ++x) {
      n += 1, sw += w[x], sh += h[x], sww += double(w[x]) * w[x], swh += double(w[x]) * h[x];
    }
  }
  const double var = sww - sw * sw / n;
  const double gain = var > 1e-9 ? (swh - sw * sh / n) / var : 1;
  const double offset = (sh - gain * sw) / n;
  int moved = 0, evidence = 0;
  for (int y = box.y; y < box.br().y; ++y) {
    const std::uint8_t* m = marks_.ptr<std::uint8_t>(y);
    const std::uint8_t* h = halves_[newest_].ptr<std::uint8_t>(y);
    const std::uint8_t* w = warped_short_.ptr<std::uint8_t>(y);
    for (int x = box.x; x < box.br().x; ++x) {
      if (!m[x]) continue;
      ++evidence;
      moved += std::abs(h[x] - (gain * w[x] + offset)) > short_threshold_;
    }
  }
  return 2 * moved < evidence;
}

// hull_: the convex hull of `label`'s evidence (its rows' ends are enough); false for none.
bool MovingObjectFinder::hull_of(int label, const cv::Rect& box) {
  points_.clear();
  for (int y = box.y; y < box.br().y; ++y) {
    const std::uint8_t* m = marks_.ptr<std::uint8_t>(y);
    const std::int32_t* l = labels_.row(y);
    int first = -1, last = -1;
    for (int x = box.x; x < box.br().x; ++x)
      if (m[x] && l[x] == label) {
        if (first < 0) first = x;
        last = x;
      }
    if (first < 0) continue;
    points_.emplace_back(first, y);
    if (last != first) points_.emplace_back(last, y);
  }
  if (points_.size() < 3) return false;
  monotone_hull(points_, hull_);
  return hull_.size() >= 3;
}

// A region continues a run of the last frame's when its centre is within its size of one of
// them and its area within a factor two.
void MovingObjectFinder::continue_runs() {
  for (Region& r : regions_) {
    for (const Region& before : last_regions_) {
      const double reach = std::sqrt(std::max(r.area, before.area));
      const double ratio = r.area / before.area;
      const cv::Point2d d = r.centre - before.centre;
      if (d.dot(d) <= reach * reach && ratio >= 0.5 && ratio <= 2)
        r.streak = std::max(r.streak, before.streak + 1);
    }
  }
  last_regions_ = regions_;
}

// The region closed (grown and shrunk by the grouping radius) with its holes filled; its hull
// when that covers under solid_share of it (texture scattered over the object, not an outline);
// brought to the working size.
void MovingObjectFinder::draw_silhouette(const Region& r, cv::Mat& silhouette) {
  const cv::Rect frame(0, 0, half_size_.width, half_size_.height);
  const int grow = radius_ + 1;
  const cv::Rect box =
      (boxes_[r.label] + cv::Size(2 * grow, 2 * grow) - cv::Point(grow, grow)) & frame;
  half_silhouette_.setTo(0);
  cv::Mat own = filled_(box), closed = closed_(box);
  for (int y = 0; y < box.height; ++y) {
    const std::uint8_t* m = marks_.ptr<std::uint8_t>(box.y + y) + box.x;
    const std::int32_t* l = labels_.row(box.y + y) + box.x;
    std::uint8_t* o = own.ptr<std::uint8_t>(y);
    for (int x = 0; x < box.width; ++x) o[x] = m[x] && l[x] == r.label;
  }
  const int side = 2 * radius_ + 1;
  cv::Mat sums = sums_(box), rows = row_sums_(box);
  box_sum(own, radius_, rows, column_sums_, sums);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x)
      own.at<std::uint8_t>(y, x) = sums.at<std::uint16_t>(y, x) > 0;
  box_sum(own, radius_, rows, column_sums_, sums);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x)
      closed.at<std::uint8_t>(y, x) = sums.at<std::uint16_t>(y, x) >= side * side;
  // Holes: the regions of the closed region's complement that do not reach the box's edge.
  holes_.label(ImageView(closed.data, closed.cols, closed.rows, closed.step), true);
  touches_.assign(static_cast<std::size_t>(holes_.count()) + 1, 0);
  for (int y = 0; y < box.height; ++y) {
    const std::int32_t* l = holes_.row(y);
    if (y == 0 || y == box.height - 1)
      for (int x = 0; x < box.width; ++x) touches_[l[x]] = 1;
    touches_[l[0]] = touches_[l[box.width - 1]] = 1;
  }
  int solid = 0;
  cv::Mat out = half_silhouette_(box);
  for (int y = 0; y < box.height; ++y) {
    const std::int32_t* l = holes_.row(y);
    const std::uint8_t* c = closed.ptr<std::uint8_t>(y);
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < box.width; ++x) solid += o[x] = c[x] || !touches_[l[x]];
  }
  if (solid < params_.solid_share * r.area) {
    half_silhouette_.setTo(0);
    if (hull_of(r.label, boxes_[r.label])) fill_convex(hull_, half_silhouette_);
  }
  silhouette.create(size_, CV_8U);
  for (int y = 0; y < size_.height; ++y) {
    const std::uint8_t* h =
        half_silhouette_.ptr<std::uint8_t>(std::min(y / 2, half_size_.height - 1));
    std::uint8_t* s = silhouette.ptr<std::uint8_t>(y);
    for (int x = 0; x < size_.width; ++x) s[x] = h[std::min(x / 2, half_size_.width - 1)] ? 255 : 0;
  }
}

}  // namespace projtrack
