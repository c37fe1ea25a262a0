#include <cmath>
#include <gtest/gtest.h>

#include "arm_fixture.h"

using namespace vrrw_control_test;

TEST(ArmController, FakeRobotFollowsTheInterpolantExactly)
{
  const std::vector<std::string> names = { "r_a", "r_b" };
  FakeRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(2));
  const auto plan = arm.plan(ramp(names, 1.0, 2.0), 0.5, 0.0);  // starts at 0.5 s
  ASSERT_TRUE(plan.validation.ok()) << plan.validation.message;
  arm.start(plan, Tolerances::uniform(2, 0.0, 0.01, 0.0, 0.5), 0.0);
  const TrajectoryInterpolator reference(ramp(names, 1.0, 2.0));
  ArmController::Outcome outcome = ArmController::Outcome::None;
  double max_error = 0.0;
  for (int k = 0; k <= 400 && outcome == ArmController::Outcome::None; ++k)
  {
    const double t = 0.01 * k;
    robot.read(t, 0.01);
    const auto c = arm.update(t);
    robot.write(t, 0.01);
    outcome = c.outcome;
    max_error = std::max(max_error, std::abs(robot.state().positions[1] - reference.sample(t - 0.5).positions[1]));
  }
  EXPECT_EQ(outcome, ArmController::Outcome::Succeeded);
  EXPECT_LT(max_error, 1e-12);
  EXPECT_DOUBLE_EQ(robot.state().positions[0], 1.0);
  EXPECT_FALSE(arm.moving());
}

TEST(ArmController, HoldsTheFirstMeasuredStateOfALateHardware)
{
  const std::vector<std::string> names = { "r_a", "r_b" };
  FakeRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(2));
  robot.reset({ 0.7, -1.2 });  // a physics robot reports its state only after construction
  const auto c = arm.update(0.0);
  EXPECT_EQ(c.desired.positions, (std::vector<double>{ 0.7, -1.2 }));
  EXPECT_EQ(robot.command().positions, (std::vector<double>{ 0.7, -1.2 }));
}

TEST(ArmController, PathAndGoalTolerancesAbort)
{
  const std::vector<std::string> names = { "r_a" };
  for (int mode = 0; mode < 2; ++mode)
  {
    LaggingRobot robot(names, 0.05);
    ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(1));
    const auto plan = arm.plan(ramp(names, 0.5, 1.0), 0.0, 0.0);
    ASSERT_TRUE(plan.validation.ok());
    const auto tol =
        mode == 0 ? Tolerances::uniform(1, 0.02, 0.0, 0.0, 0.0) : Tolerances::uniform(1, 0.0, 0.01, 0.0, 0.3);
    arm.start(plan, tol, 0.0);
    ArmController::Cycle c;
    double end = 0.0;
    for (int k = 0; k < 300 && c.outcome == ArmController::Outcome::None; ++k)
    {
      robot.read(0.01 * k, 0.01);
      c = arm.update(0.01 * k);
      robot.write(0.01 * k, 0.01);
      end = 0.01 * k;
    }
    if (mode == 0)
    {
      EXPECT_EQ(c.outcome, ArmController::Outcome::PathToleranceViolated);
      EXPECT_NE(c.message.find("r_a"), std::string::npos);
      EXPECT_LT(end, 0.05);
    }
    else
    {
      EXPECT_EQ(c.outcome, ArmController::Outcome::GoalToleranceViolated);
      EXPECT_NEAR(end, 1.3, 0.011);
    }
  }
}

TEST(ArmController, StopDeceleratesSmoothly)
{
  const std::vector<std::string> names = { "r_a" };
  FakeRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(1));
  const auto plan = arm.plan(ramp(names, 2.0, 2.0), 0.0, 0.0);
  ASSERT_TRUE(plan.validation.ok()) << plan.validation.message;
  arm.start(plan, noTolerances(1), 0.0);
  double previous_q = 0.0, previous_v = 0.0, max_step = 0.0, max_dv = 0.0;
  const double dt = 0.001;
  for (int k = 0; k < 2000; ++k)
  {
    const double t = dt * k;
    if (k == 1000)
      arm.stop(t);
    const auto c = arm.update(t);
    robot.write(t, dt);
    max_step = std::max(max_step, std::abs(c.desired.positions[0] - previous_q));
    if (k > 0)
      max_dv = std::max(max_dv, std::abs(c.desired.velocities[0] - previous_v) / dt);
    previous_q = c.desired.positions[0];
    previous_v = c.desired.velocities[0];
  }
  EXPECT_LE(max_step, 1.5 * dt + 1e-9);  // peak velocity of the cubic is 1.5 rad/s
  EXPECT_LE(max_dv, 4.0 + 1e-6);
  EXPECT_FALSE(arm.moving());
  EXPECT_EQ(previous_v, 0.0);
  EXPECT_LT(previous_q, 2.0);
}

TEST(ArmController, StrictPreemptionStopsThenStartsFromRest)
{
  const std::vector<std::string> names = { "r_a" };
  FakeRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(1, false));
  arm.start(arm.plan(ramp(names, 2.0, 2.0), 0.0, 0.0), noTolerances(1), 0.0);
  double t = 0.0;
  for (; t < 1.0; t += 0.001)
    arm.update(t), robot.write(t, 0.001);
  // the strict gate checks the goal against the rest state after the stop: 1.0 s at 1.5 rad/s, 4 rad/s^2
  const double rest = robot.state().positions[0] + 0.5 * 1.5 * 1.5 / 4.0;
  auto from_rest = ramp(names, 0.0, 1.5, rest);
  const auto second = arm.plan(from_rest, t, t);
  ASSERT_TRUE(second.validation.ok()) << second.validation.message;
  EXPECT_NEAR(second.start - t, 1.5 / 4.0, 1e-3);  // after the stop
  arm.start(second, noTolerances(1), t);
  double previous_v = robot.state().velocities[0], max_dv = 0.0;
  ArmController::Outcome outcome = ArmController::Outcome::None;
  for (; t < 6.0 && outcome == ArmController::Outcome::None; t += 0.001)
  {
    const auto c = arm.update(t);
    robot.write(t, 0.001);
    max_dv = std::max(max_dv, std::abs(c.desired.velocities[0] - previous_v) / 0.001);
    previous_v = c.desired.velocities[0];
    outcome = c.outcome;
  }
  EXPECT_EQ(outcome, ArmController::Outcome::Succeeded);
  EXPECT_NEAR(robot.state().positions[0], 0.0, 1e-12);
  EXPECT_LE(max_dv, 4.0 + 1e-6);
}
