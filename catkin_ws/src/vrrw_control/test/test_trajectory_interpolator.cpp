#include <gtest/gtest.h>
#include <vrrw_control/trajectory_interpolator.h>

using vrrw_control::TrajectoryInterpolator;
using vrrw_trajectory::JointTrajectory;
using vrrw_trajectory::TrajectoryPoint;

namespace
{
TrajectoryPoint point(double t, std::vector<double> q, std::vector<double> v = {}, std::vector<double> a = {})
{
  TrajectoryPoint p;
  p.time = t;
  p.positions = q;
  p.velocities = v;
  p.accelerations = a;
  return p;
}
}  // namespace

TEST(TrajectoryInterpolator, PassesThroughEveryPoint)
{
  JointTrajectory tr;
  tr.joint_names = { "a", "b" };
  tr.points = { point(0.0, { 0, 0 }, { 0, 0 }), point(1.0, { 1, -1 }, { 0.5, 0 }), point(2.5, { 0, 2 }, { 0, 0 }) };
  const TrajectoryInterpolator interp(tr);
  for (const auto& p : tr.points)
  {
    const auto s = interp.sample(p.time);
    for (size_t j = 0; j < 2; ++j)
    {
      EXPECT_NEAR(s.positions[j], p.positions[j], 1e-12);
    }
  }
  EXPECT_NEAR(interp.sample(1.0 - 1e-9).velocities[0], 0.5, 1e-6);
  EXPECT_NEAR(interp.sample(1.0 + 1e-9).velocities[0], 0.5, 1e-6);
}

TEST(TrajectoryInterpolator, PicksOrderFromAvailableFields)
{
  JointTrajectory lin, quin;
  lin.points = { point(0.0, { 0 }), point(2.0, { 1 }) };
  quin.points = { point(0.0, { 0 }, { 0 }, { 0 }), point(2.0, { 1 }, { 0 }, { 0 }) };
  EXPECT_NEAR(TrajectoryInterpolator(lin).sample(0.5).positions[0], 0.25, 1e-12);
  // minimum-jerk profile at tau = 1/4: 10 s^3 - 15 s^4 + 6 s^5
  const double s = 0.25, expected = 10 * s * s * s - 15 * s * s * s * s + 6 * s * s * s * s * s;
  EXPECT_NEAR(TrajectoryInterpolator(quin).sample(0.5).positions[0], expected, 1e-12);
}

TEST(TrajectoryInterpolator, HoldsEndsWithZeroVelocity)
{
  JointTrajectory tr;
  tr.points = { point(1.0, { 2 }, { 1 }), point(2.0, { 3 }, { 1 }) };
  const TrajectoryInterpolator interp(tr);
  EXPECT_EQ(interp.sample(0.0).positions[0], 2.0);
  EXPECT_EQ(interp.sample(9.0).positions[0], 3.0);
  EXPECT_EQ(interp.sample(9.0).velocities[0], 0.0);
  EXPECT_EQ(interp.segmentAt(1.5), 0u);
}
