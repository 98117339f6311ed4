// Automatic acquisition with the edges model: which seeds it fills, and what that costs.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "acquisition/motion_acquisition.hpp"
#include "core/plausibility.hpp"
#include "projtrack/estimator.hpp"
#include "projtrack/work_budget.hpp"

namespace projtrack {
namespace {

ImageView view(const cv::Mat& m) { return ImageView(m.data, m.cols, m.rows, m.step); }

// A closed outline (the object) in an open frame, and a disc around it that changed between two
// frames: the first seed (the motion's centroid) is in the object, the others spread over the
// background around it, which is one region larger than any object may be. Pixel filling from a
// seed in that region is cut short by the area limit, and a seed that such a fill took in would
// be cut short again: it is not filled, so acquisition costs a few fills, not one per seed.
TEST(MotionAcquisition, SeedsInARegionTooLargeToBeTheObjectAreNotFilledAgain) {
  constexpr int kW = 320, kH = 240;
  const Point2i centre{230, 120};
  cv::Mat edges(kH, kW, CV_8U, cv::Scalar(0));
  cv::circle(edges, {centre.x, centre.y}, 20, cv::Scalar(255), 1, cv::LINE_8);
  cv::Mat before(kH, kW, CV_8U, cv::Scalar(0)), after = before.clone();
  cv::circle(after, {centre.x, centre.y}, 70, cv::Scalar(255), cv::FILLED);

  TrackerParams tp;  // auto acquisition, the compact moving region of several seeds
  ASSERT_EQ(tp.acquisition, Acquisition::Auto);
  ASSERT_EQ(tp.strategy, AutoAcquisition::CompactMovingRegion);
  const double limit = area_limit(kW, kH, tp, nullptr);
  const Params params;

  // What one fill of the background costs (from a point of the changed ring, cut short).
  std::uint64_t background_fill = 0, object_fill = 0;
  Features object;
  {
    auto est = make_estimator(Method::PixelFilling);
    EstimateOptions o;
    o.area_limit = limit;
    WorkBudget b;
    o.budget = &b;
    const Features f = est->estimate(view(edges), {centre.x - 60, centre.y}, params, o);
    ASSERT_GT(f.area, limit) << "the background is one region larger than the limit";
    background_fill = b.spent();
    WorkBudget c;
    o.budget = &c;
    object = est->estimate(view(edges), centre, params, o);
    object_fill = c.spent();
  }

  auto est = make_estimator(Method::PixelFilling);
  MotionAcquisition acquisition;
  std::string why;
  WorkBudget first;
  EXPECT_FALSE(acquisition.acquire(view(before), view(edges), *est, params, limit, tp, first, why));
  WorkBudget budget;
  const std::optional<Features> f =
      acquisition.acquire(view(after), view(edges), *est, params, limit, tp, budget, why);
  ASSERT_TRUE(f) << why;
  EXPECT_EQ(f->area, object.area);
  EXPECT_EQ(f->bbox, object.bbox);
  // Twelve seeds besides the centroid, nearly all in the background: filled one by one, they
  // would cost about twelve background fills.
  EXPECT_LE(budget.spent(), object_fill + 3 * background_fill)
      << "acquisition spent " << budget.spent() << " units; one background fill costs "
      << background_fill;
}

}  // namespace
}  // namespace projtrack
