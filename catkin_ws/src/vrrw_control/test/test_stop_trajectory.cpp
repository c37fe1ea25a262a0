#include <cmath>
#include <gtest/gtest.h>
#include <vrrw_control/stop_trajectory.h>
#include <vrrw_control/trajectory_interpolator.h>

TEST(StopTrajectory, DeceleratesWithinBoundsWithoutJumps)
{
  vrrw_control::JointSample s(2);
  s.positions = { 0.5, -1.0 };
  s.velocities = { 1.0, -0.4 };
  const std::vector<double> decel = { 2.0, 2.0 };
  const auto stop = vrrw_control::makeStopTrajectory({ "a", "b" }, s, decel);
  ASSERT_EQ(stop.points.size(), 2u);
  EXPECT_NEAR(stop.points[1].time, 0.5, 1e-12);
  const vrrw_control::TrajectoryInterpolator interp(stop);
  double previous = s.positions[0];
  for (int k = 0; k <= 100; ++k)
  {
    const double t = 0.5 * k / 100.0;
    const auto x = interp.sample(t);
    EXPECT_NEAR(x.positions[0], 0.5 + t - t * t, 1e-12);  // q0 + v0 t - v0 t^2 / 2T
    EXPECT_LE(std::abs(x.accelerations[0]), 2.0 + 1e-9);
    EXPECT_LE(std::abs(x.accelerations[1]), 2.0 + 1e-9);
    EXPECT_LE(std::abs(x.positions[0] - previous), 1.0 * 0.005 + 1e-12);
    previous = x.positions[0];
  }
  EXPECT_EQ(interp.sample(0.5).velocities[0], 0.0);
}

TEST(StopTrajectory, AtRestIsOnePoint)
{
  vrrw_control::JointSample s(1);
  s.positions = { 0.3 };
  EXPECT_EQ(vrrw_control::makeStopTrajectory({ "a" }, s, { 1.0 }).points.size(), 1u);
}
