#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <vrrw_control/trajectory_validator.h>

using namespace vrrw_control;
using vrrw_trajectory::JointTrajectory;
using vrrw_trajectory::TrajectoryPoint;

namespace
{
std::vector<JointLimits> limits()
{
  std::vector<JointLimits> l(3);
  const char* names[] = { "r_a", "r_b", "r_c" };
  for (int j = 0; j < 3; ++j)
  {
    l[j].name = names[j];
    l[j].has_position_limits = true;
    l[j].min_position = -1.0;
    l[j].max_position = 1.0;
    l[j].max_velocity = 2.0;
    l[j].max_acceleration = 5.0;
  }
  return l;
}

JointTrajectory goal()
{
  JointTrajectory g;
  g.joint_names = { "r_c", "r_a", "r_b" };  // any order
  for (int i = 0; i < 3; ++i)
  {
    TrajectoryPoint p;
    p.time = 0.5 * i;
    p.positions = { 0.1 * i, 0.2 * i, 0.0 };
    p.velocities = { 0.0, 0.0, 0.0 };
    g.points.push_back(p);
  }
  return g;
}

Validation check(const JointTrajectory& g, ValidationOptions o = {})
{
  return TrajectoryValidator(limits(), o).validate(g, JointSample(3));
}
}  // namespace

TEST(TrajectoryValidator, AcceptsAnyJointOrderAndReorders)
{
  const auto v = check(goal());
  ASSERT_TRUE(v.ok()) << v.message;
  EXPECT_EQ(v.executable.joint_names[0], "r_a");
  EXPECT_DOUBLE_EQ(v.executable.points[2].positions[0], 0.4);  // r_a was second in the goal
  EXPECT_DOUBLE_EQ(v.executable.points[2].positions[2], 0.2);
}

TEST(TrajectoryValidator, RejectsDuplicateUnknownMissingJoints)
{
  auto g = goal();
  g.joint_names[1] = "r_c";
  auto v = check(g);
  EXPECT_EQ(v.error, Validation::Error::InvalidJoints);
  EXPECT_EQ(v.joint, "r_c");
  g = goal();
  g.joint_names[1] = "other_x";
  v = check(g);
  EXPECT_EQ(v.error, Validation::Error::InvalidJoints);
  EXPECT_EQ(v.joint, "other_x");
  g = goal();
  g.joint_names.pop_back();
  for (auto& p : g.points)
    p.positions.pop_back(), p.velocities.pop_back();
  v = check(g);
  EXPECT_EQ(v.error, Validation::Error::InvalidJoints);
  EXPECT_EQ(v.joint, "r_b");
  EXPECT_NE(v.message.find("missing"), std::string::npos);
}

TEST(TrajectoryValidator, RejectsNonIncreasingTimes)
{
  auto g = goal();
  g.points[2].time = g.points[1].time;
  const auto v = check(g);
  EXPECT_EQ(v.error, Validation::Error::InvalidGoal);
  EXPECT_EQ(v.point, 2);
  EXPECT_NE(v.message.find("does not increase"), std::string::npos);
}

TEST(TrajectoryValidator, RejectsNonFiniteValues)
{
  auto g = goal();
  g.points[1].velocities[2] = std::numeric_limits<double>::quiet_NaN();
  const auto v = check(g);
  EXPECT_EQ(v.point, 1);
  EXPECT_EQ(v.joint, "r_b");
  EXPECT_NE(v.message.find("not finite"), std::string::npos);
}

TEST(TrajectoryValidator, RejectsPositionVelocityAccelerationBeyondLimits)
{
  auto g = goal();
  g.points[2].positions[1] = 1.5;
  auto v = check(g);
  EXPECT_EQ(v.point, 2);
  EXPECT_EQ(v.joint, "r_a");
  EXPECT_NE(v.message.find("outside limits"), std::string::npos);

  g = goal();
  g.points[1].velocities[0] = -2.5;
  v = check(g);
  EXPECT_EQ(v.point, 1);
  EXPECT_EQ(v.joint, "r_c");
  EXPECT_NE(v.message.find("velocity -2.5 exceeds limit 2"), std::string::npos);

  g = goal();
  for (auto& p : g.points)
    p.accelerations = { 0.0, 0.0, 0.0 };
  g.points[1].accelerations[2] = 6.0;
  v = check(g);
  EXPECT_EQ(v.point, 1);
  EXPECT_EQ(v.joint, "r_b");
  EXPECT_NE(v.message.find("acceleration"), std::string::npos);
}

TEST(TrajectoryValidator, RejectsTooFastInterpolant)
{
  auto g = goal();
  for (auto& p : g.points)
    p.velocities.clear();
  g.points[2].time = 0.55;  // r_a moves 0.2 rad in 0.05 s: 4 rad/s
  const auto v = check(g);
  EXPECT_EQ(v.point, 2);
  EXPECT_EQ(v.joint, "r_a");
  EXPECT_NE(v.message.find("interpolated velocity"), std::string::npos);
}

TEST(TrajectoryValidator, StartToleranceRejectsInTheStrictGate)
{
  auto g = goal();
  for (auto& p : g.points)
    p.positions[1] += 0.3;  // r_a starts 0.3 rad away
  const auto v = check(g);
  EXPECT_EQ(v.point, 0);
  EXPECT_EQ(v.joint, "r_a");
  EXPECT_NE(v.message.find("start tolerance"), std::string::npos);
}

TEST(TrajectoryValidator, SpliceAtRestBlendsToAFarFirstPointWithinTheLimits)
{
  auto g = goal();
  for (auto& p : g.points)
    p.positions[1] += 0.3;  // r_a starts 0.3 rad away: blended to, never refused
  const auto v = TrajectoryValidator(limits(), {}).splice(g, JointSample(3));
  ASSERT_TRUE(v.ok()) << v.message;
  EXPECT_TRUE(v.blended);
  ASSERT_EQ(v.executable.points.size(), 4u);
  EXPECT_EQ(v.executable.points[0].positions[0], 0.0);
  EXPECT_EQ(v.executable.points[1].positions[0], 0.3);
  // the goal's points carry velocities: a rest-to-rest cubic over 0.3 rad, peak velocity 1.5 dq / T <= 2,
  // peak acceleration 6 dq / T^2 <= 5
  const double shortest = std::max(1.5 * 0.3 / 2.0, std::sqrt(6.0 * 0.3 / 5.0));
  EXPECT_GE(v.executable.points[1].time, shortest * 0.999);
  EXPECT_LE(v.executable.points[1].time, shortest * 1.02);
  EXPECT_NEAR(v.executable.points[3].time - v.executable.points[1].time, 1.0, 1e-12);  // the goal's own timing
}

TEST(TrajectoryValidator, SpliceDropsPassedPointsAndStartsFromTheMovingState)
{
  auto g = goal();  // points at 0, 0.5, 1.0 s
  JointSample moving(3);
  moving.velocities = { 0.2, -0.1, 0.05 };
  moving.accelerations = { 0.5, 0.0, -0.3 };
  moving.positions = { 0.12, 0.0, 0.05 };  // 0.3 s from point 1 without passing a limit
  const auto v = TrajectoryValidator(limits(), {}).splice(g, moving, 0.2);  // 0.2 s of the goal have passed
  ASSERT_TRUE(v.ok()) << v.message;
  ASSERT_EQ(v.executable.points.size(), 3u);  // the splice point and the goal's points 1 and 2
  EXPECT_EQ(v.executable.points[0].velocities, moving.velocities);
  EXPECT_EQ(v.executable.points[0].accelerations, moving.accelerations);
  EXPECT_NEAR(v.executable.points[1].time, 0.3, 1e-12);  // 0.5 s of the goal, 0.2 s in
  EXPECT_DOUBLE_EQ(v.executable.points[1].positions[0], 0.2);
  EXPECT_FALSE(v.blended);
  // the splice never refuses for the start tolerance, but still names a point beyond the limits
  g.points[2].positions[0] = 1.5;  // r_c
  const auto bad = TrajectoryValidator(limits(), {}).splice(g, moving, 0.2);
  EXPECT_EQ(bad.point, 2);
  EXPECT_EQ(bad.joint, "r_c");
}

TEST(TrajectoryValidator, SpliceKeepsTheLastPointWhenAllHavePassed)
{
  JointTrajectory g;
  g.joint_names = { "r_a", "r_b", "r_c" };
  TrajectoryPoint target;
  target.positions = { 0.4, -0.2, 0.1 };  // one point at time 0: "go there", as scripts send it
  g.points = { target };
  const auto v = TrajectoryValidator(limits(), {}).splice(g, JointSample(3));
  ASSERT_TRUE(v.ok()) << v.message;
  EXPECT_TRUE(v.blended);
  ASSERT_EQ(v.executable.points.size(), 2u);
  EXPECT_EQ(v.executable.points[1].positions, target.positions);
  EXPECT_EQ(v.executable.points[1].velocities, (std::vector<double>{ 0.0, 0.0, 0.0 }));
}

TEST(TrajectoryValidator, PrependsCurrentStateWhenFirstPointIsLater)
{
  auto g = goal();
  for (auto& p : g.points)
    p.time += 1.0;
  const auto v = check(g);
  ASSERT_TRUE(v.ok()) << v.message;
  ASSERT_EQ(v.executable.points.size(), 4u);
  EXPECT_EQ(v.executable.points[0].time, 0.0);
}

TEST(TrajectoryValidator, RejectsWrongSizes)
{
  auto g = goal();
  g.points[1].positions.pop_back();
  EXPECT_EQ(check(g).point, 1);
  g = goal();
  g.points.clear();
  EXPECT_EQ(check(g).error, Validation::Error::InvalidGoal);
}
