// The settings bundle and the enums' name tables: one default each, one check, one name per value.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "projtrack/names.hpp"
#include "projtrack/settings.hpp"

namespace projtrack {
namespace {

TEST(Settings, DefaultsAreTheStructsAndValid) {
  const Settings s;
  EXPECT_EQ(s.method, Method::GapTolerantFilling);
  EXPECT_EQ(s.params.rays, Params{}.rays);
  EXPECT_EQ(s.edges.low, EdgeParams{}.low);
  EXPECT_EQ(s.tracker.max_work, TrackerParams{}.max_work);
  EXPECT_EQ(validate(s), "");
}

TEST(Settings, ValidateNamesWhatIsWrong) {
  const auto why = [](auto change) {
    Settings s;
    change(s);
    return validate(s);
  };
  EXPECT_NE(why([](Settings& s) { s.params.rays = 0; }).find("rays"), std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.edges.low = 200; }), "");  // above the high threshold
  EXPECT_NE(why([](Settings& s) { s.edges.low = -1; }).find("edge_threshold_low"),
            std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.edges.blur = 17; }).find("blur"), std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.tracker.max_work = -1; }).find("max_work"), std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.tracker.max_work = NAN; }).find("max_work"), std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.tracker.leak_factor = 1; }).find("leak_factor"),
            std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.tracker.filter.min_cutoff = 0; }).find("min_cutoff"),
            std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.tracker.push.threshold = INFINITY; }).find("push"),
            std::string::npos);
  EXPECT_NE(why([](Settings& s) { s.method = static_cast<Method>(99); }).find("method"),
            std::string::npos);
  // The tracker's own per-frame check: max_work alone of its parameters.
  TrackerParams tp;
  EXPECT_EQ(validate(tp), "");
  tp.max_work = kMaxMaxWork * 2;
  EXPECT_NE(validate(tp).find("max_work"), std::string::npos);
}

template <class E>
void expect_table_round_trips() {
  std::set<std::string> nicks;
  std::set<int> values;
  for (const NameRow<E>& row : names_of<E>()) {
    EXPECT_TRUE(nicks.insert(row.nick).second) << row.nick;
    EXPECT_TRUE(values.insert(static_cast<int>(row.value)).second) << row.nick;
    EXPECT_EQ(from_nick<E>(row.nick), row.value);
    EXPECT_STREQ(nick_of(row.value), row.nick);
    EXPECT_TRUE(row.description && *row.description) << row.nick;
  }
  EXPECT_FALSE(from_nick<E>("no-such-name"));
  EXPECT_STREQ(nick_of(static_cast<E>(99)), "unknown");
}

TEST(Names, EveryTableRoundTripsWithUniqueNicksAndValues) {
  expect_table_round_trips<Method>();
  expect_table_round_trips<EdgeDetector>();
  expect_table_round_trips<Acquisition>();
  expect_table_round_trips<ObjectModelKind>();
}

TEST(Names, TheMethodsAreTheTableOfMethods) {
  ASSERT_EQ(std::size(kMethodNames), std::size(kMethods));
  for (const MethodInfo& m : kMethods) EXPECT_STREQ(nick_of(m.method), m.nick);
  EXPECT_EQ(nick_list<Acquisition>(), "manual, center, auto");
}

}  // namespace
}  // namespace projtrack
