#include <cmath>
#include <gtest/gtest.h>
#include <vrrw_control/splice_segment.h>

using namespace vrrw_control;

namespace
{
std::vector<JointLimits> limits(double velocity, double acceleration)
{
  JointLimits l;
  l.name = "r_a";
  l.max_velocity = velocity;
  l.max_acceleration = acceleration;
  return { l };
}

JointSample state(double q, double v, double a)
{
  JointSample s(1);
  s.positions = { q };
  s.velocities = { v };
  s.accelerations = { a };
  return s;
}
}  // namespace

TEST(SpliceSegment, RestToRestIsTheQuinticTimeOptimum)
{
  // a rest-to-rest quintic over dq peaks at 1.875 dq / T (velocity) and 5.7735 dq / T^2 (acceleration)
  for (const double dq : { 0.05, 0.5, 2.0 })
  {
    const double T = shortestSplice(SplineSegment::Order::Quintic, state(0, 0, 0), state(dq, 0, 0), 0.0, limits(1.5, 4.0));
    const double optimum = std::max(1.875 * dq / 1.5, std::sqrt(5.7735 * dq / 4.0));
    EXPECT_GE(T, optimum * 0.999) << dq;
    EXPECT_LE(T, optimum * 1.02) << dq;
  }
}

TEST(SpliceSegment, FromAMovingStateTheShortestDurationKeepsTheLimitsAndNoShorterOneDoes)
{
  const auto from = state(0.3, 1.2, -2.0), to = state(-0.4, 0.0, 0.0);
  const auto l = limits(1.5, 4.0);
  const double T = shortestSplice(SplineSegment::Order::Quintic, from, to, 0.01, l);
  ASSERT_TRUE(std::isfinite(T));
  EXPECT_TRUE(checkSplice(SplineSegment::Order::Quintic, from, to, T, l).ok());
  const auto shorter = checkSplice(SplineSegment::Order::Quintic, from, to, 0.95 * T, l);
  EXPECT_FALSE(shorter.ok());
  EXPECT_EQ(shorter.joint, "r_a");
}

TEST(SpliceSegment, AGivenDurationThatKeepsTheLimitsIsKept)
{
  EXPECT_DOUBLE_EQ(shortestSplice(SplineSegment::Order::Quintic, state(0, 0, 0), state(0.1, 0, 0), 2.0, limits(1.5, 4.0)), 2.0);
  EXPECT_DOUBLE_EQ(shortestSplice(SplineSegment::Order::Quintic, state(0, 0, 0), state(0, 0, 0), 0.0, limits(1.5, 4.0)), kShortestSplice);
}

TEST(SpliceSegment, PositionLimitsNoDurationCanKeepAreNamed)
{
  auto l = limits(2.0, 4.0);
  l[0].has_position_limits = true;
  l[0].min_position = -1.0;
  l[0].max_position = 1.0;
  // at the upper limit, heading out at full speed: every quintic overshoots
  const auto from = state(1.0, 2.0, 0.0), to = state(1.0, 0.0, 0.0);
  EXPECT_TRUE(std::isinf(shortestSplice(SplineSegment::Order::Quintic, from, to, 0.0, l)));
  const auto why = checkSplice(SplineSegment::Order::Quintic, from, to, 1.0, l);
  EXPECT_NE(why.reason.find("position"), std::string::npos) << why.reason;
}
