// Parameters, method and status names.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <set>
#include <string>

#include "projtrack/estimator.hpp"
#include "projtrack/flow_model_params.hpp"
#include "projtrack/method.hpp"
#include "projtrack/params.hpp"
#include "projtrack/status.hpp"

namespace projtrack {
namespace {

TEST(Params, DefaultsAreValid) { EXPECT_EQ(validate(Params{}), ""); }

TEST(Params, EveryRangeEndIsAcceptedAndOneBeyondIsNot) {
  const auto check = [](auto set, auto lo, auto hi, const char* name) {
    Params p;
    set(p, lo);
    EXPECT_EQ(validate(p), "") << name << " = " << lo;
    set(p, hi);
    EXPECT_EQ(validate(p), "") << name << " = " << hi;
    set(p, lo - 1);
    EXPECT_NE(validate(p).find(name), std::string::npos) << name << " = " << lo - 1;
    set(p, hi + 1);
    EXPECT_NE(validate(p).find(name), std::string::npos) << name << " = " << hi + 1;
  };
  check([](Params& p, int v) { p.rays = v; }, kMinRays, kMaxRays, "rays");
  check([](Params& p, int v) { p.recursion = v, p.rays = 3; }, kMinRecursion, kMaxRecursion,
        "recursion");
  check([](Params& p, int v) { p.block_size = v; }, 1, kMaxCellSize, "block_size");
  check([](Params& p, int v) { p.grid_size = v; }, 1, kMaxCellSize, "grid_size");
  check([](Params& p, int v) { p.max_iterations = v; }, 1, kMaxIterations, "max_iterations");
  check([](Params& p, double v) { p.convergence = v; }, 0.0, kMaxConvergence, "convergence");
  check([](Params& p, int v) { p.seed_radius = v; }, 0, kMaxSeedRadius, "seed_radius");
}

TEST(EstimateOptions, TheAreaLimitIsCheckedAsTheParametersAre) {
  EXPECT_EQ(validate(EstimateOptions{}), "");
  for (double v : {0.0, kMaxAreaLimit}) {
    EstimateOptions o;
    o.area_limit = v;
    EXPECT_EQ(validate(o), "") << v;
  }
  for (double v : {-1.0, 2 * kMaxAreaLimit, std::nan(""), HUGE_VAL}) {
    EstimateOptions o;
    o.area_limit = v;
    EXPECT_NE(validate(o).find("area_limit"), std::string::npos) << v;
  }
  // An estimator says so as it says a parameter is out of range.
  const std::uint8_t free_pixel = 0;
  EstimateOptions bad;
  bad.area_limit = -1;
  const Features f = make_estimator(Method::PixelFilling)
                         ->estimate(ImageView(&free_pixel, 1, 1, 1), {0, 0}, Params{}, bad);
  EXPECT_EQ(f.status, EstimateStatus::InvalidParameters);
  EXPECT_NE(f.detail.find("area_limit"), std::string::npos);
}

TEST(Method, NamesRoundTrip) {
  std::set<std::string_view> names;
  for (Method m : kAllMethods) {
    EXPECT_EQ(method_from_name(method_name(m)), m);
    names.insert(method_name(m));
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kMethodCount));
  EXPECT_FALSE(method_from_name("flood").has_value());
  EXPECT_EQ(method_name(Method::GridFilling), "grid-filling");
}

TEST(Method, TheTableHasOneRowPerValueInEnumOrder) {
  ASSERT_EQ(std::size(kAllMethods), std::size(kMethods));
  for (int i = 0; i < kMethodCount; ++i) {
    const MethodInfo& info = kMethods[i];
    EXPECT_EQ(info.method, kAllMethods[i]);
    EXPECT_EQ(static_cast<int>(info.method), i);
    EXPECT_EQ(&method_info(info.method), &info);
    // GStreamer enum nicks and CSV columns: lower-case words joined by hyphens, no spaces.
    const std::string_view nick = info.nick;
    EXPECT_FALSE(nick.empty());
    EXPECT_EQ(nick.find_first_not_of("abcdefghijklmnopqrstuvwxyz-"), std::string_view::npos)
        << nick;
    EXPECT_GT(std::string_view(info.description).size(), 10u) << nick;
    EXPECT_EQ(info.family == Family::Rays, is_ray_method(info.method)) << nick;
    ASSERT_NE(info.make, nullptr) << nick;
    EXPECT_NE(info.make(), nullptr) << nick;
  }
}

TEST(Method, AnIntegerThatIsNoMethodHasDefinedAnswers) {
  const auto bad = static_cast<Method>(kMethodCount);
  EXPECT_FALSE(is_method(bad));
  EXPECT_FALSE(is_method(static_cast<Method>(-1)));
  EXPECT_EQ(method_name(bad), "unknown");
  EXPECT_FALSE(is_ray_method(bad));
  EXPECT_EQ(make_estimator(bad), nullptr);
}

TEST(Status, NamesAreDistinctAndFeaturesOnlyWhereComputed) {
  std::set<std::string_view> estimate_names, track_names;
  for (int s = 0; s <= static_cast<int>(kLastEstimateStatus); ++s)
    estimate_names.insert(status_name(static_cast<EstimateStatus>(s)));
  for (int s = 0; s <= static_cast<int>(kLastTrackStatus); ++s)
    track_names.insert(status_name(static_cast<TrackStatus>(s)));
  EXPECT_EQ(estimate_names.size(), 10u);
  EXPECT_EQ(track_names.size(), 12u);
  EXPECT_EQ(estimate_names.count("unknown") + track_names.count("unknown"), 0u);
  EXPECT_EQ(status_name(static_cast<EstimateStatus>(10)), "unknown");
  EXPECT_EQ(status_name(static_cast<TrackStatus>(12)), "unknown");
  // Every name the element can post, each once: the two kinds share the names of what the
  // tracker reports as it came.
  std::set<std::string_view> all = estimate_names;
  all.insert(track_names.begin(), track_names.end());
  EXPECT_EQ(all.size(), 14u);
  EXPECT_TRUE(has_features(EstimateStatus::ReachedBorder));
  EXPECT_FALSE(has_features(EstimateStatus::InnerPointOnEdge));
  EXPECT_TRUE(has_features(TrackStatus::CoversFrame));
  EXPECT_FALSE(has_features(TrackStatus::Lost));
  EXPECT_FALSE(has_features(TrackStatus::OverBudget));
  EXPECT_FALSE(has_features(TrackStatus::Interrupted));
  EXPECT_FALSE(has_features(TrackStatus::Occluded));
}

// The tracker reports an estimate it takes as it is under the estimate's own name, with or
// without features as the estimate; one without a free pixel at the inner point is refused.
TEST(Status, AReportedEstimateKeepsItsNameAndItsFeatures) {
  for (int i = 0; i <= static_cast<int>(kLastEstimateStatus); ++i) {
    const auto s = static_cast<EstimateStatus>(i);
    const TrackStatus t = reported_status(s);
    if (s == EstimateStatus::InnerPointOutside || s == EstimateStatus::InnerPointOnEdge) {
      EXPECT_EQ(t, TrackStatus::Lost) << status_name(s);
      continue;
    }
    EXPECT_EQ(status_name(t), status_name(s));
    EXPECT_EQ(has_features(t), has_features(s)) << status_name(s);
  }
}

TEST(FlowModelParams, EveryMemberOutOfItsRangeIsNamed) {
  EXPECT_EQ(validate(FlowModelParams{}), "");
  struct Case {
    const char* name;
    double FlowModelParams::*member;
    double bad;
  };
  const Case cases[] = {{"work_pixels", &FlowModelParams::work_pixels, 999},
                        {"flow_span", &FlowModelParams::flow_span, -1},
                        {"box_pixels", &FlowModelParams::box_pixels, 99},
                        {"prior_spread", &FlowModelParams::prior_spread, -0.1},
                        {"prior_floor", &FlowModelParams::prior_floor, 0.5},
                        {"learning_rate", &FlowModelParams::learning_rate, 1.5},
                        {"first_share", &FlowModelParams::first_share, -1},
                        {"local_colour_weight", &FlowModelParams::local_colour_weight, 1.5},
                        {"colour_ring", &FlowModelParams::colour_ring, 0},
                        {"motion_ring", &FlowModelParams::motion_ring, NAN},
                        {"motion_weight", &FlowModelParams::motion_weight, -2},
                        {"min_separation", &FlowModelParams::min_separation, INFINITY},
                        {"memory_weight", &FlowModelParams::memory_weight, 2},
                        {"memory_refresh", &FlowModelParams::memory_refresh, -0.5},
                        {"memory_fade", &FlowModelParams::memory_fade, 1},
                        {"keep_share", &FlowModelParams::keep_share, 1.01},
                        {"new_motion_share", &FlowModelParams::new_motion_share, -0.1},
                        {"new_core", &FlowModelParams::new_core, 2}};
  for (const Case& c : cases) {
    FlowModelParams p;
    p.*c.member = c.bad;
    EXPECT_NE(validate(p).find(std::string("flow.") + c.name), std::string::npos)
        << c.name << " = " << c.bad << ": " << validate(p);
  }
  for (const int cells : {0, 17}) {
    FlowModelParams p;
    p.local_colour_cells = cells;
    EXPECT_NE(validate(p).find("flow.local_colour_cells"), std::string::npos) << cells;
  }
}

}  // namespace
}  // namespace projtrack
