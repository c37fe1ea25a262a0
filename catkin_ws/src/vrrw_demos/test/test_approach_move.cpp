#include <gtest/gtest.h>

#include <vrrw_demos/approach_move.h>
#include <vrrw_demos/demo_error.h>

using namespace vrrw_demos;

TEST(ApproachMove, TheFarthestJointAveragesAFifthOfItsLimitAtRestAtBothEnds)
{
  const std::vector<std::string> joints{ "a", "b", "c" };
  // b moves 0.6 rad with a 3 rad/s limit: 0.6 / (0.2 * 3) = 1 s; c moves 1 rad with a 10 rad/s limit: 0.5 s
  const auto move = approachMove(joints, { 0.0, 0.0, 0.0 }, { 0.1, -0.6, 1.0 }, { 3.0, 3.0, 10.0 });
  ASSERT_EQ(move.points.size(), 2u);
  EXPECT_EQ(move.joint_names, joints);
  EXPECT_DOUBLE_EQ(move.points[1].time, 1.0);
  EXPECT_EQ(move.points[0].positions, (std::vector<double>{ 0.0, 0.0, 0.0 }));
  EXPECT_EQ(move.points[1].positions, (std::vector<double>{ 0.1, -0.6, 1.0 }));
  EXPECT_EQ(move.points[0].velocities, std::vector<double>(3, 0.0));
  EXPECT_EQ(move.points[1].velocities, std::vector<double>(3, 0.0));
  // no distance: the shortest move; another fraction scales the time
  EXPECT_DOUBLE_EQ(approachMove(joints, { 1, 2, 3 }, { 1, 2, 3 }, { 1, 1, 1 }).points[1].time, 0.5);
  ApproachOptions faster;
  faster.velocity_fraction = 0.4;
  EXPECT_DOUBLE_EQ(approachMove(joints, { 0, 0, 0 }, { 0.1, -0.6, 1.0 }, { 3, 3, 10 }, faster).points[1].time, 0.5);
}

TEST(ApproachMove, WrongSizesAndLimitsAreNamed)
{
  EXPECT_THROW(approachMove({ "a", "b" }, { 0 }, { 0, 0 }, { 1, 1 }), DemoError);
  try
  {
    approachMove({ "a", "b" }, { 0, 0 }, { 0, 1 }, { 1, 0 });
    FAIL() << "no error";
  }
  catch (const DemoError& e)
  {
    EXPECT_EQ(std::string(e.what()), "approach: joint b: velocity limit 0.000000 is not positive");
  }
}
