#include <gtest/gtest.h>
#include <vrrw_control/spline_segment.h>

using vrrw_control::SplineSegment;

TEST(SplineSegment, QuinticMeetsBothEndStates)
{
  const SplineSegment s(SplineSegment::Order::Quintic, 0.7, 0.1, -0.3, 2.0, 1.2, 0.5, -1.0);
  double q, v, a;
  s.sample(0.0, q, v, a);
  EXPECT_NEAR(q, 0.1, 1e-12);
  EXPECT_NEAR(v, -0.3, 1e-12);
  EXPECT_NEAR(a, 2.0, 1e-12);
  s.sample(0.7, q, v, a);
  EXPECT_NEAR(q, 1.2, 1e-12);
  EXPECT_NEAR(v, 0.5, 1e-12);
  EXPECT_NEAR(a, -1.0, 1e-11);
}

TEST(SplineSegment, CubicMeetsEndPositionsAndVelocities)
{
  const SplineSegment s(SplineSegment::Order::Cubic, 2.0, -1.0, 0.2, 0.0, 1.0, -0.4, 0.0);
  double q, v, a;
  s.sample(2.0, q, v, a);
  EXPECT_NEAR(q, 1.0, 1e-12);
  EXPECT_NEAR(v, -0.4, 1e-12);
  s.sample(1.0, q, v, a);  // Hermite midpoint: (q0+q1)/2 + T(v0-v1)/8
  EXPECT_NEAR(q, 0.0 + 2.0 * (0.2 + 0.4) / 8.0, 1e-12);
}

TEST(SplineSegment, LinearHasConstantVelocity)
{
  const SplineSegment s(SplineSegment::Order::Linear, 0.5, 1.0, 9.0, 9.0, 2.0, 9.0, 9.0);
  double q, v, a;
  s.sample(0.25, q, v, a);
  EXPECT_NEAR(q, 1.5, 1e-12);
  EXPECT_NEAR(v, 2.0, 1e-12);
  EXPECT_NEAR(a, 0.0, 1e-12);
}

TEST(SplineSegment, ClampsOutsideItsInterval)
{
  const SplineSegment s(SplineSegment::Order::Cubic, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0);
  double q, v, a;
  s.sample(3.0, q, v, a);
  EXPECT_NEAR(q, 1.0, 1e-12);
  EXPECT_NEAR(v, 0.0, 1e-12);
}
