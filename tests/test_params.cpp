// Parameters, method and status names.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <set>
#include <string>

#include "estimator.hpp"
#include "method.hpp"
#include "params.hpp"
#include "status.hpp"

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
  check([](Params& p, double v) { p.area_limit = v; }, 0.0, kMaxAreaLimit, "area_limit");
  Params p;
  p.area_limit = std::nan("");
  EXPECT_NE(validate(p).find("area_limit"), std::string::npos);
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
  std::set<std::string_view> names;
  for (int s = 0; s <= static_cast<int>(Status::InvalidParameters); ++s)
    names.insert(status_name(static_cast<Status>(s)));
  EXPECT_EQ(names.size(), 11u);
  EXPECT_TRUE(has_features(Status::ReachedBorder));
  EXPECT_FALSE(has_features(Status::InnerPointOnEdge));
}

}  // namespace
}  // namespace projtrack
