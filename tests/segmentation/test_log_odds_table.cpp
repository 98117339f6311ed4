// The prior's log-odds by table against the logarithm it stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "segmentation/log_odds_table.hpp"

namespace projtrack {
namespace {

TEST(LogOddsTable, IsWithinAHundredthOfANatOfTheLogarithm) {
  LogOddsTable table;
  for (const double floor : {0.02, 0.1, 0.3}) {
    table.build(floor);
    for (int i = 0; i <= 1000; ++i) {
      const double q = std::clamp(i / 1000.0, floor, 1 - floor);
      EXPECT_NEAR(table(static_cast<float>(i / 1000.0)), std::log(q / (1 - q)), 0.01)
          << "floor " << floor << ", q " << i / 1000.0;
    }
  }
}

TEST(LogOddsTable, ReadsValuesOutsideTheUnitIntervalAndNaNAsItsEnds) {
  LogOddsTable table;
  table.build(0.02);
  const float low = std::log(0.02f / 0.98f);
  EXPECT_NEAR(table(-3.0f), low, 1e-5);
  EXPECT_NEAR(table(std::numeric_limits<float>::quiet_NaN()), low, 1e-5);
  EXPECT_NEAR(table(7.0f), -low, 1e-5);
}

}  // namespace
}  // namespace projtrack
