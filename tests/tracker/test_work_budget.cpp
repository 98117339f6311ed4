// Bounded work (issue 16): every estimate and every frame of the tracker spends from a budget
// counted in work, never in time, on content made to cost as much as possible (the adversarial
// set: noise, fresh random dots, checkerboards inverted on every frame, combs, mazes, spirals),
// through every method, both object models and every way a track starts. What is asserted is
// work and status; no test here measures a time.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>
#include <thread>

#include "adversarial.hpp"
#include "projtrack/color_conversion.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/tracker.hpp"
#include "projtrack/work_budget.hpp"
#include "scenes.hpp"

namespace projtrack {
namespace {

using synthetic::adversarial_frame;
using synthetic::Adversary;
using synthetic::AdversaryInfo;
using synthetic::kAdversaries;

ImageView view(const cv::Mat& m) {
  return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
}

TEST(WorkBudget, SpendsChecksAndStaysRunOut) {
  WorkBudget b(100);
  b.spend(60);
  EXPECT_EQ(b.spent(), 60u);
  EXPECT_EQ(b.left(), 40u);
  EXPECT_FALSE(b.exhausted(40)) << "exactly what is left can be done";
  EXPECT_FALSE(b.ran_out());
  EXPECT_TRUE(b.exhausted(41));
  EXPECT_TRUE(b.ran_out());
  EXPECT_TRUE(b.exhausted()) << "a budget that said stop says it again";
  EXPECT_FALSE(b.interrupted());

  WorkBudget unlimited;
  EXPECT_TRUE(unlimited.unlimited());
  unlimited.spend(WorkBudget::kUnlimited - 1);
  unlimited.spend(10);  // saturates
  EXPECT_EQ(unlimited.spent(), WorkBudget::kUnlimited);

  std::atomic<bool> stop{false};
  WorkBudget flagged(WorkBudget::kUnlimited, &stop);
  EXPECT_FALSE(flagged.exhausted(1000));
  stop = true;
  EXPECT_TRUE(flagged.exhausted());
  EXPECT_TRUE(flagged.interrupted());
  EXPECT_FALSE(flagged.ran_out()) << "stopped, not out of work";
}

TEST(WorkBudget, FrameLimitScalesWithThePixelsAndZeroIsUnlimited) {
  TrackerParams tp;
  tp.max_work = 8;
  EXPECT_EQ(frame_work_limit(1920, 1080, tp), 8u * 1920 * 1080);
  EXPECT_EQ(frame_work_limit(1, 1, tp), 12u << 20) << "a small frame counts as 1.5 megapixels";
  EXPECT_EQ(frame_work_limit(640, 480, tp), 12u << 20);
  tp.max_work = 0.01;
  EXPECT_EQ(frame_work_limit(1, 1, tp), kLeastFrameWork) << "and still gets some";
  tp.max_work = 0;
  EXPECT_EQ(frame_work_limit(1920, 1080, tp), WorkBudget::kUnlimited);
}

TEST(WorkBudget, TheLeastCostOfAnEstimateCountsEveryCast) {
  Params p;
  p.rays = 8;
  // Ray casting: one fan, and the inner-point update's; a fill, the update's alone.
  EXPECT_EQ(least_estimate_cost(Method::RayCasting, p), 16 * (kCostPerRay + kCostPerRayStep));
  p.rays = 1024;
  p.recursion = 2;
  // Recursive: n + n² rays in one iteration; pixel-filling reads no recursion.
  EXPECT_EQ(least_estimate_cost(Method::RecursiveRayCasting, p),
            (1024 + 1024 * 1024 + 1024) * (kCostPerRay + kCostPerRayStep));
  EXPECT_EQ(least_estimate_cost(Method::PixelFilling, p), 1024 * (kCostPerRay + kCostPerRayStep));
}

// Edge maps that cost the estimators the most: the adversarial frames read as edges (non-zero =
// edge), and their Canny edges.
struct EdgeCase {
  std::string name;
  cv::Mat edges;
};

std::vector<EdgeCase> adversarial_edges(int w, int h) {
  std::vector<EdgeCase> out;
  EdgeMap map;
  for (const AdversaryInfo& a : kAdversaries) {
    const cv::Mat f = adversarial_frame(a.kind, w, h, 0);
    out.push_back({std::string(a.name) + " as edges", f});
    const ImageView e = map.detect(view(f), EdgeParams{});
    out.push_back({std::string(a.name) + " through Canny",
                   cv::Mat(h, w, CV_8U, const_cast<std::uint8_t*>(e.data), e.stride).clone()});
  }
  return out;
}

bool same(const Features& a, const Features& b) {
  return a.status == b.status && a.centroid.x == b.centroid.x && a.centroid.y == b.centroid.y &&
         a.area == b.area && a.bbox == b.bbox && a.inner_point == b.inner_point &&
         a.iterations == b.iterations && a.pixels_visited == b.pixels_visited &&
         a.rays_cast == b.rays_cast;
}

// Every method, from two points of every adversarial edge map: with a budget at least what the
// estimate costs, the same answer as without one; with half of that, it stops within the
// overshoot bound, says so, and has no features.
TEST(WorkBudget, EveryEstimatorStopsWithinItsBudgetAndOtherwiseAnswersAsWithout) {
  constexpr int kW = 320, kH = 240;
  Params heavy;  // more rays per cast than the defaults, so the ray methods have work to stop
  heavy.rays = 24;
  heavy.recursion = 3;
  heavy.max_iterations = 8;
  heavy.convergence = 0;
  int stopped = 0, cases = 0;
  for (const EdgeCase& c : adversarial_edges(kW, kH)) {
    for (const MethodInfo& m : kMethods) {
      auto est = m.make();
      for (const Params& p : {Params{}, heavy}) {
        for (Point2i seed : {Point2i{kW / 2, kH / 2}, Point2i{kW / 5, kH / 3}}) {
          const std::string what = c.name + ", " + m.nick + " from " + std::to_string(seed.x) +
                                   "," + std::to_string(seed.y) + ", " + std::to_string(p.rays) +
                                   " rays";
          WorkBudget unlimited;
          EstimateOptions o;
          o.budget = &unlimited;
          const Features free = est->estimate(view(c.edges), seed, p, o);
          const Features none = est->estimate(view(c.edges), seed, p);
          ASSERT_TRUE(same(free, none)) << what << ": an unlimited budget changes nothing";
          const std::uint64_t cost = unlimited.spent();

          WorkBudget enough(cost);
          o.budget = &enough;
          const Features f = est->estimate(view(c.edges), seed, p, o);
          ASSERT_TRUE(same(f, free)) << what << ": a budget of exactly its cost suffices";
          EXPECT_EQ(enough.spent(), cost) << what << ": the count is deterministic";

          if (cost < 2000) continue;  // too little to halve meaningfully
          ++cases;
          WorkBudget half(cost / 2);
          o.budget = &half;
          const Features cut = est->estimate(view(c.edges), seed, p, o);
          EXPECT_LE(half.spent(), cost / 2 + overshoot_bound(kW, kH)) << what;
          if (cut.status == EstimateStatus::OverBudget) {
            ++stopped;
            EXPECT_FALSE(cut.valid()) << what;
            EXPECT_FALSE(cut.detail.empty()) << what;
            EXPECT_LT(cut.pixels_visited, free.pixels_visited + 1) << what;
          } else {
            // Only a last stretch past the checkpoints can finish over the limit.
            EXPECT_TRUE(same(cut, free)) << what << ": " << status_name(cut.status);
          }
        }
      }
    }
  }
  std::printf("estimates halved: %d, stopped by the budget: %d\n", cases, stopped);
  EXPECT_GT(stopped, cases / 2) << "the budget must be exercised";
}

TEST(WorkBudget, AStopFlagSetBeforeAnEstimateStopsItBeforeAnyWork) {
  const test::Scene s = test::disc_scene();
  std::atomic<bool> stop{true};
  for (const MethodInfo& m : kMethods) {
    WorkBudget b(WorkBudget::kUnlimited, &stop);
    EstimateOptions o;
    o.budget = &b;
    const Features f = m.make()->estimate(s.edge_view(), {100, 90}, Params{}, o);
    EXPECT_EQ(f.status, EstimateStatus::Interrupted) << m.nick;
    EXPECT_EQ(f.pixels_visited, 0u) << m.nick;
    EXPECT_FALSE(f.valid()) << m.nick;
  }
}

// How a track starts, for both object models: from a point or a box at the frame's centre, or by
// acquisition.
struct Start {
  const char* name;
  bool point, box;
  Acquisition acquisition;
};
constexpr Start kStarts[] = {{"seeded", true, false, Acquisition::Auto},
                             {"box", false, true, Acquisition::Auto},
                             {"auto", false, false, Acquisition::Auto},
                             {"center", false, false, Acquisition::Center}};

// The adversarial set through the tracker as the element runs it (edges computed by the tracker,
// the default budget): every method, both models, every start. Each frame's work stays within
// its budget (and the overshoot bound); a frame that runs out says so, without features; the
// next frame gets a budget of its own; the count is the same on a second run.
TEST(WorkBudget, EveryFrameOfTheAdversarialSetStaysWithinTheBudget) {
  constexpr int kW = 320, kH = 240, kFrames = 4;
  // The budget of 8 × the frame's own pixels (a frame this small counts as kLeastBudgetPixels at
  // the default max_work): the adversarial set runs out of it.
  TrackerParams defaults;
  defaults.max_work = 8.0 * kW * kH / kLeastBudgetPixels;
  const std::uint64_t limit = frame_work_limit(kW, kH, defaults);
  const std::uint64_t bound = limit + overshoot_bound(kW, kH);
  std::vector<std::vector<cv::Mat>> sequences;
  for (const AdversaryInfo& a : kAdversaries) {
    sequences.emplace_back();
    for (int i = 0; i < kFrames; ++i)
      sequences.back().push_back(adversarial_frame(a.kind, kW, kH, i));
  }
  int frames = 0, over = 0, over_edges = 0;
  std::uint64_t most = 0;
  for (ObjectModelKind model : {ObjectModelKind::Edges, ObjectModelKind::Flow}) {
    for (const Start& start : kStarts) {
      for (const MethodInfo& m : kMethods) {
        for (std::size_t k = 0; k < sequences.size(); ++k) {
          TrackerParams tp = defaults;
          tp.model = model;
          tp.acquisition = start.acquisition;
          // The edges model's frames run twice: the same work both times.
          const bool twice = model == ObjectModelKind::Edges;
          Tracker t, again;
          for (Tracker* tr : {&t, &again}) {
            if (start.point) tr->seed({kW / 2, kH / 2});
            if (start.box) tr->seed_box({kW / 3, kH / 3, kW / 3, kH / 3});
          }
          for (int i = 0; i < kFrames; ++i) {
            const std::string what =
                std::string(model == ObjectModelKind::Edges ? "edges" : "flow") + ", " +
                start.name + ", " + m.nick + ", " + kAdversaries[k].name + " frame " +
                std::to_string(i);
            const ImageView g = view(sequences[k][i]);
            const TrackResult r = t.track(g, EdgeParams{}, i / 30.0, m.method, Params{}, tp);
            const TrackResult r2 =
                twice ? again.track(g, EdgeParams{}, i / 30.0, m.method, Params{}, tp) : r;
            ++frames;
            most = std::max(most, r.work);
            EXPECT_EQ(r.work_limit, limit) << what;
            EXPECT_LE(r.work, bound) << what << ": " << status_name(r.status);
            EXPECT_EQ(r.work, r2.work) << what << ": work is counted, not timed";
            EXPECT_EQ(r.status, r2.status) << what;
            if (r.status == TrackStatus::OverBudget) {
              ++over;
              over_edges += model == ObjectModelKind::Edges;
              EXPECT_FALSE(r.detail.empty()) << what;
              EXPECT_GE(r.work, limit / 2) << what << ": ran out with half of it left";
            }
            EXPECT_NE(r.status, TrackStatus::Interrupted) << what;
          }
        }
      }
    }
  }
  std::printf(
      "%d frames, %d over budget (%d with the edges model); the most work %.2f× the "
      "frame's pixels, the budget %.2f×\n",
      frames, over, over_edges, static_cast<double>(most) / (kW * kH),
      static_cast<double>(limit) / (kW * kH));
  EXPECT_GT(over_edges, 0) << "the adversarial set must exhaust the edges model's budget";
}

// A BGR frame of `kind` (flat, noise, gradient) as the tracker reads it.
struct ColourFrame {
  cv::Mat bgr;
  std::vector<std::uint8_t> planes;
  ColorView view;

  ColourFrame(const std::string& kind, int w, int h, int seed = 1) : bgr(h, w, CV_8UC3) {
    if (kind == "flat") bgr.setTo(cv::Scalar(90, 120, 150));
    if (kind == "noise") cv::RNG(seed).fill(bgr, cv::RNG::UNIFORM, 0, 256);
    if (kind == "gradient")
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<std::uint8_t>(255 * x / w),
                                              static_cast<std::uint8_t>(255 * y / h), 128);
    view = packed_rgb_to_color(bgr.data + 2, bgr.data + 1, bgr.data, 3,
                               static_cast<std::ptrdiff_t>(bgr.step), w, h, planes);
  }
};

// The flow model's starts (a cut of the box, or of squares around the click) on the pictures
// that cost GrabCut the most (a flat frame took it 16-20 s, noise and gradients hundreds of ms at
// 640×480): every frame, the start's included, within the frame's budget and the overshoot
// bound, at every size; a flat frame has nothing to cut and says so.
TEST(WorkBudget, FlowStartsOnFlatNoiseAndGradientFramesStayWithinTheBudget) {
  const cv::Size sizes[] = {{160, 120}, {640, 480}, {1280, 720}, {1920, 1080}};
  std::uint64_t most = 0;
  for (const cv::Size size : sizes) {
    const int w = size.width, h = size.height;
    for (const std::string kind : {"flat", "noise", "gradient"}) {
      for (const bool box : {true, false}) {
        TrackerParams tp;
        tp.model = ObjectModelKind::Flow;
        tp.acquisition = Acquisition::Manual;
        Tracker t;
        if (box)
          t.seed_box({w / 3, h / 3, w / 3, h / 3});
        else
          t.seed({w / 2, h / 2});
        for (int i = 0; i < 3; ++i) {
          const ColourFrame f(kind, w, h, i + 1);
          const TrackResult r =
              t.track(f.view, EdgeParams{}, i / 30.0, Method::GapTolerantFilling, Params{}, tp);
          const std::string what = kind + " " + std::to_string(w) + "x" + std::to_string(h) +
                                   (box ? " from a box" : " from a point") + ", frame " +
                                   std::to_string(i) + ": " + std::string(status_name(r.status)) +
                                   " " + r.detail;
          EXPECT_LE(r.work, r.work_limit + overshoot_bound(w, h)) << what;
          most = std::max(most, r.work);
          if (kind == "flat") {
            EXPECT_NE(r.detail.find("nothing to cut"), std::string::npos) << what;
          }
        }
      }
    }
  }
  std::printf("the most work of a frame: %.1fM units\n", most / 1e6);
}

// The stop flag set while a start runs (a click on 1080p noise, its costliest) ends the frame
// `interrupted` within milliseconds: each of the start's stages checks it before it runs.
TEST(WorkBudget, TheStopFlagEndsAFlowStart) {
  const ColourFrame noise("noise", 1920, 1080);
  TrackerParams tp;
  tp.model = ObjectModelKind::Flow;
  tp.acquisition = Acquisition::Manual;
  std::atomic<bool> stop{true};
  Tracker t;
  t.set_stop_flag(&stop);
  t.seed({960, 540});
  const TrackResult before =
      t.track(noise.view, EdgeParams{}, 0, Method::GapTolerantFilling, Params{}, tp);
  EXPECT_EQ(before.status, TrackStatus::Interrupted) << before.detail;
  EXPECT_EQ(before.work, 0U);
  stop = false;
  t.seed({960, 540});
  const TrackResult whole =
      t.track(noise.view, EdgeParams{}, 0, Method::GapTolerantFilling, Params{}, tp);
  ASSERT_NE(whole.status, TrackStatus::Interrupted);
  using Clock = std::chrono::steady_clock;
  std::atomic<bool> started{false};
  Clock::time_point set_at;
  std::thread stopper([&] {
    while (!started) std::this_thread::yield();
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    set_at = Clock::now();
    stop = true;
  });
  TrackResult r;
  Clock::time_point returned;
  for (int i = 0; i < 1000 && r.status != TrackStatus::Interrupted; ++i) {
    t.seed({960, 540});  // a start on every frame
    started = true;
    r = t.track(noise.view, EdgeParams{}, 0, Method::GapTolerantFilling, Params{}, tp);
    returned = Clock::now();
  }
  stopper.join();
  ASSERT_EQ(r.status, TrackStatus::Interrupted) << r.detail;
  const double ms = std::chrono::duration<double, std::milli>(returned - set_at).count();
  EXPECT_LT(ms, 50) << "from the flag to the frame's end";
  std::printf("stopped %.2f ms after the flag, having done %.1fM of a start's %.1fM units\n", ms,
              r.work / 1e6, whole.work / 1e6);
}

// A bright disc on a dark background, moving right by `dx` px.
cv::Mat disc(int w, int h, int dx = 0) {
  cv::Mat g(h, w, CV_8U, cv::Scalar(40));
  cv::circle(g, {w / 2 + dx, h / 2}, h / 4, cv::Scalar(220), cv::FILLED);
  return g;
}

// Automatic acquisition on fresh dots (every part of the frame changes alike) takes nothing: no
// region moves apart from the picture, and it says so. A disc moving on fresh sensor noise still
// stands out and is found.
TEST(WorkBudget, AutomaticAcquisitionTakesNothingInAFrameThatChangesEvenly) {
  constexpr int kW = 320, kH = 240;
  TrackerParams tp;
  tp.acquisition = Acquisition::Auto;
  Tracker t;
  TrackResult r;
  for (int i = 0; i < 8; ++i) {
    r = t.track(view(adversarial_frame(Adversary::Dots5, kW, kH, i)), EdgeParams{}, i / 30.0,
                Method::GapTolerantFilling, Params{}, tp);
    EXPECT_EQ(r.status, TrackStatus::Searching) << i << ": " << r.detail;
  }
  EXPECT_FALSE(r.detail.empty());
  Tracker found;
  cv::RNG rng(5);
  bool acquired = false;
  for (int i = 0; i < 12 && !acquired; ++i) {
    cv::Mat g = disc(kW, kH, 3 * i - 18), noise(kH, kW, CV_8U);
    rng.fill(noise, cv::RNG::NORMAL, 0, 8);
    cv::add(g, noise, g);
    r = found.track(view(g), EdgeParams{}, i / 30.0, Method::GapTolerantFilling, Params{}, tp);
    acquired = r.acquired;
  }
  EXPECT_TRUE(acquired) << status_name(r.status) << ": " << r.detail;
}

// An estimate the budget stopped is not a measurement: the track reports its last accepted
// features as `over-budget`, `patience` of them in a row are tolerated and the next drops the
// track, as for refused estimates; with work enough again, it tracks.
TEST(WorkBudget, AFrameOverBudgetIsARefusalByTheUsualRules) {
  constexpr int kW = 320, kH = 240;
  TrackerParams tp;
  tp.model = ObjectModelKind::Edges;
  tp.acquisition = Acquisition::Manual;
  Params cheap, costly;
  costly.rays = 256;  // 65 536 rays per cast, 1.3M units at the least: above the budget below
  costly.recursion = 2;
  Tracker t;
  t.seed({kW / 2, kH / 2});
  const TrackResult first =
      t.track(view(disc(kW, kH)), EdgeParams{}, 0, Method::RecursiveRayCasting, cheap, tp);
  ASSERT_EQ(first.status, TrackStatus::Ok) << first.detail;
  // 3M units: more than one cast of the costly settings costs at the least (rays blocked at
  // once), far less than their rays across the disc cost.
  tp.max_work = 3e6 / kLeastBudgetPixels;
  for (int i = 1; i <= tp.patience + 1; ++i) {
    const TrackResult r = t.track(view(disc(kW, kH, i)), EdgeParams{}, i / 30.0,
                                  Method::RecursiveRayCasting, costly, tp);
    ASSERT_EQ(r.status, TrackStatus::OverBudget) << i << ": " << r.detail;
    EXPECT_NE(r.detail.find("budget"), std::string::npos) << r.detail;
    if (i <= tp.patience) {
      EXPECT_TRUE(r.features.valid()) << "the last accepted features are kept";
      EXPECT_EQ(r.features.centroid.x, first.features.centroid.x);
      EXPECT_TRUE(r.inner_point.has_value());
    } else {
      EXPECT_NE(r.detail.find("dropped"), std::string::npos) << r.detail;
      EXPECT_FALSE(r.inner_point.has_value());
    }
  }
  t.seed({kW / 2, kH / 2});
  const TrackResult back =
      t.track(view(disc(kW, kH)), EdgeParams{}, 1, Method::RecursiveRayCasting, cheap, tp);
  EXPECT_EQ(back.status, TrackStatus::Ok) << back.detail;
}

TEST(WorkBudget, SettingsThatCanNeverFitAreRefusedAtOnce) {
  constexpr int kW = 640, kH = 480;
  Params p;
  p.rays = 1024;
  p.recursion = 2;  // valid: 2^20 rays per cast
  ASSERT_TRUE(validate(p).empty());
  TrackerParams tp;
  tp.model = ObjectModelKind::Edges;
  Tracker t;
  t.seed({kW / 2, kH / 2});
  const TrackResult r =
      t.track(view(disc(kW, kH)), EdgeParams{}, 0, Method::RecursiveRayCasting, p, tp);
  EXPECT_EQ(r.status, TrackStatus::InvalidParameters);
  EXPECT_NE(r.detail.find("work units"), std::string::npos) << r.detail;
  EXPECT_EQ(r.work, 0u) << "refused before any work";
  // A method that reads no recursion casts 1024 rays only: it fits.
  const TrackResult fill =
      t.track(view(disc(kW, kH)), EdgeParams{}, 0, Method::PixelFilling, p, tp);
  EXPECT_NE(fill.status, TrackStatus::InvalidParameters) << fill.detail;
  // The same settings with a budget raised far enough are not refused (the frame is small, so
  // its rays are short).
  tp.max_work = 20000;
  Tracker small;
  small.seed({20, 15});
  const TrackResult raised =
      small.track(view(disc(40, 30)), EdgeParams{}, 0, Method::RecursiveRayCasting, p, tp);
  EXPECT_NE(raised.status, TrackStatus::InvalidParameters) << raised.detail;
}

// The stop flag: a frame that would run for minutes (no budget, a million rays per cast on a
// uniform 1080p frame, so every ray crosses it, up to a thousand iterations) is stopped at its
// next checkpoint once another thread sets the flag; it ends `interrupted` having done far less
// than one cast's work, and the track is kept as it was. With the flag cleared, the next frame
// tracks.
TEST(WorkBudget, TheStopFlagEndsAHugeFrameAndKeepsTheTrack) {
  constexpr int kW = 1920, kH = 1080;
  const cv::Mat uniform(kH, kW, CV_8U, cv::Scalar(128));
  TrackerParams tp;
  tp.model = ObjectModelKind::Edges;
  tp.acquisition = Acquisition::Manual;
  tp.max_work = 0;
  Params huge;
  huge.rays = 1024;
  huge.recursion = 2;
  huge.max_iterations = 1000;
  huge.convergence = 0;
  std::atomic<bool> stop{false};
  Tracker t;
  t.set_stop_flag(&stop);
  const Point2i inner{kW / 2 - 100, kH / 2};  // inside the disc of the last frame
  t.seed(inner);
  std::thread stopper([&] { stop = true; });  // at any moment of the frame, or before it
  const TrackResult r =
      t.track(view(uniform), EdgeParams{}, 0, Method::RecursiveRayCasting, huge, tp);
  stopper.join();
  EXPECT_EQ(r.status, TrackStatus::Interrupted) << r.detail;
  EXPECT_FALSE(r.detail.empty());
  // One cast: 2^20 rays of hundreds of steps each.
  EXPECT_LT(r.work, least_estimate_cost(Method::RecursiveRayCasting, huge) * 10);
  ASSERT_TRUE(r.inner_point.has_value()) << "the track waits where it was";
  EXPECT_EQ(*r.inner_point, inner);
  const TrackResult again =
      t.track(view(uniform), EdgeParams{}, 0.033, Method::RecursiveRayCasting, huge, tp);
  EXPECT_EQ(again.status, TrackStatus::Interrupted) << "stopped while the flag is set";
  EXPECT_EQ(again.work, 0u);
  stop = false;
  const TrackResult next =
      t.track(view(disc(kW, kH)), EdgeParams{}, 0.067, Method::GridFilling, Params{}, tp);
  EXPECT_TRUE(has_features(next.status)) << status_name(next.status) << " " << next.detail;
}

}  // namespace
}  // namespace projtrack
