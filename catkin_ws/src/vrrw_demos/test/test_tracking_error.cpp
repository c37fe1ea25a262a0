#include <gtest/gtest.h>

#include <cmath>

#include <vrrw_demos/tracking_error.h>

using namespace vrrw_demos;

TEST(TrackingError, CountsOnlyTheMotionAndSkipsMissingJoints)
{
  const auto expected = [](double t) { return std::vector<double>{ t, -t }; };
  const std::vector<MeasuredState> measured{
    { -0.1, { 5.0, 5.0 } },                 // before the motion: not counted
    { 0.0, { 0.0, 0.0 } },                  // exact
    { 0.5, { 0.503, -0.504 } },             // 3 and 4 mrad
    { 1.0, { 1.0, std::nan("") } },         // the second joint missing from the message
    { 1.5, { 9.0, 9.0 } },                  // after: not counted
  };
  const TrackingError error = trackingError(measured, expected, 1.0);
  EXPECT_EQ(error.states, 3u);
  EXPECT_EQ(error.values, 5u);
  EXPECT_NEAR(error.max, 0.004, 1e-12);
  EXPECT_NEAR(error.rms, std::sqrt((0.003 * 0.003 + 0.004 * 0.004) / 5.0), 1e-12);
  const TrackingError none = trackingError({}, expected, 1.0);
  EXPECT_EQ(none.values, 0u);
  EXPECT_EQ(none.rms, 0.0);
}
