#include <gtest/gtest.h>

#include <vrrw_trajectory/msg_conversions.h>

TEST(MsgConversions, RoundTripKeepsEveryValueAndTime)
{
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = { "a", "b" };
  trajectory.points.push_back({ 0.0, { 0.1, -0.2 }, { 0.0, 0.0 }, {} });
  trajectory.points.push_back({ 1.2345678901, { 0.3, 0.4 }, { 0.5, -0.6 }, { 1.0, 2.0 } });
  const auto msg = vrrw_trajectory::toMsg(trajectory);
  ASSERT_EQ(msg.points.size(), 2u);
  EXPECT_NEAR(msg.points[1].time_from_start.toSec(), 1.2345678901, 1e-9);
  EXPECT_TRUE(msg.points[0].accelerations.empty());
  const auto back = vrrw_trajectory::fromMsg(msg);
  EXPECT_EQ(back.joint_names, trajectory.joint_names);
  ASSERT_EQ(back.points.size(), 2u);
  EXPECT_NEAR(back.points[1].time, 1.2345678901, 1e-9);
  EXPECT_EQ(back.points[1].positions, trajectory.points[1].positions);
  EXPECT_EQ(back.points[1].velocities, trajectory.points[1].velocities);
  EXPECT_EQ(back.points[1].accelerations, trajectory.points[1].accelerations);
}
