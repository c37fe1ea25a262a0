// ArmController joining motions (splice), following streamed targets, holding measured poses.
#include <cmath>
#include <gtest/gtest.h>

#include "arm_fixture.h"

using namespace vrrw_control_test;

namespace
{
/// Largest per-cycle change of desired position and velocity, and largest |velocity| and
/// |acceleration| (finite differences of the desired velocity), over a run of cycles.
struct Smoothness
{
  double max_step = 0.0, max_velocity_step = 0.0, max_velocity = 0.0, max_acceleration = 0.0;
  JointSample last;
  void add(const JointSample& desired, double dt)
  {
    if (!last.positions.empty())
      for (size_t j = 0; j < desired.size(); ++j)
      {
        max_step = std::max(max_step, std::abs(desired.positions[j] - last.positions[j]));
        const double dv = std::abs(desired.velocities[j] - last.velocities[j]);
        max_velocity_step = std::max(max_velocity_step, dv);
        max_acceleration = std::max(max_acceleration, dv / dt);
      }
    for (double v : desired.velocities)
      max_velocity = std::max(max_velocity, std::abs(v));
    last = desired;
  }
};
}  // namespace

TEST(ArmControllerSplice, ANewGoalJoinsTheRunningOneWithoutAStep)
{
  const std::vector<std::string> names = { "r_a", "r_b" };
  FakeRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(2));
  arm.start(arm.plan(ramp(names, 1.5, 2.0), 0.0, 0.0), noTolerances(2), 0.0);
  const double dt = 0.001;
  Smoothness run;
  double t = 0.0;
  for (; t < 1.0 - 1e-9; t += dt)
    run.add(arm.update(t).desired, dt), robot.write(t, dt);
  const JointSample before = run.last;
  EXPECT_GT(before.velocities[0], 1.0);  // mid-motion, near the cubic's peak of 1.125 rad/s

  // back to 0 in 1 s from a trajectory that starts at 0 s: its first point (where the arm was) is
  // dropped, the splice runs from the current desired position, velocity and acceleration
  const auto plan = arm.plan(ramp(names, 0.0, 1.0, 0.0), t, t);
  ASSERT_TRUE(plan.validation.ok()) << plan.validation.message;
  arm.start(plan, noTolerances(2), t);
  ArmController::Cycle c = arm.update(t);
  robot.write(t, dt);
  // the first cycle after the splice continues the motion: position and velocity as extrapolated
  EXPECT_NEAR(c.desired.positions[0], before.positions[0] + before.velocities[0] * dt, 4.0 * dt * dt);
  EXPECT_NEAR(c.desired.velocities[0], before.velocities[0], 4.0 * dt + 1e-9);
  run.add(c.desired, dt);
  for (t += dt; t < 8.0 && c.outcome == ArmController::Outcome::None; t += dt)
    run.add((c = arm.update(t)).desired, dt), robot.write(t, dt);
  EXPECT_EQ(c.outcome, ArmController::Outcome::Succeeded);
  EXPECT_NEAR(robot.state().positions[0], 0.0, 1e-12);
  std::cout << "splice: max |dq| per 1 ms " << run.max_step << " rad, max |dqd| per 1 ms " << run.max_velocity_step
            << " rad/s, max |qd| " << run.max_velocity << " rad/s, max |qdd| " << run.max_acceleration << " rad/s^2"
            << std::endl;
  EXPECT_LE(run.max_step, 2.0 * dt + 1e-9);              // never faster than the velocity limit
  EXPECT_LE(run.max_velocity, 2.0 + 1e-9);
  EXPECT_LE(run.max_acceleration, 4.0 * (1.0 + 1e-6));  // the limit, across the splice too
}

TEST(ArmControllerSplice, StreamedTargetsAreFollowedWithinTheLimits)
{
  // one-point trajectories 50 ms ahead at 100 Hz along a path faster than the limits allow
  const std::vector<std::string> names = { "r_a" };
  FakeRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(1));
  const double dt = 0.001;
  auto target = [](double t) { return t < 2.0 ? 1.2 * std::sin(3.0 * t) : 1.2 * std::sin(6.0); };
  Smoothness run;
  int rejected = 0;
  for (int k = 0; k < 4000; ++k)
  {
    const double t = k * dt;
    if (k % 10 == 0)
    {
      vrrw_trajectory::JointTrajectory one;
      one.joint_names = names;
      one.points.resize(1);
      one.points[0].positions = { target(t + 0.05) };
      one.points[0].time = 0.05;
      const auto plan = arm.plan(one, t, t);
      rejected += !plan.validation.ok();
      if (plan.validation.ok())
        arm.start(plan, noTolerances(1), t);
    }
    run.add(arm.update(t).desired, dt);
    robot.write(t, dt);
  }
  EXPECT_EQ(rejected, 0);
  EXPECT_LE(run.max_velocity, 2.0 * (1.0 + 1e-6));
  EXPECT_LE(run.max_acceleration, 4.0 * (1.0 + 1e-6));
  EXPECT_NEAR(robot.state().positions[0], target(4.0), 1e-9);  // and it arrives once the stream rests
}

TEST(ArmControllerSplice, AnAbortedGoalHoldsWhereTheFrozenArmIsNotWhereTheGoalWanted)
{
  // a physics step guard freezes the arm; the goal fails its tolerance and aborts; once the
  // simulation runs again the arm must stay where it was, not move on to the aborted goal's end
  const std::vector<std::string> names = { "r_a" };
  MeasuredRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(1));
  arm.start(arm.plan(ramp(names, 1.5, 2.0), 0.0, 0.0), Tolerances::uniform(1, 0.0, 0.01, 0.0, 0.2), 0.0);
  ArmController::Cycle c;
  double t = 0.0, frozen_at = 0.0;
  for (; t < 5.0 && c.outcome == ArmController::Outcome::None; t += 0.001)
  {
    if (!robot.frozen && t >= 0.8)
      robot.frozen = true, frozen_at = robot.state().positions[0];
    c = arm.update(t);
    robot.write(t, 0.001);
  }
  EXPECT_EQ(c.outcome, ArmController::Outcome::GoalToleranceViolated);
  robot.frozen = false;
  for (double end = t + 2.0; t < end; t += 0.001)
    arm.update(t), robot.write(t, 0.001);
  std::cout << "frozen at " << frozen_at << " rad, after the abort the arm rests at " << robot.state().positions[0]
            << " rad (the goal ended at 1.5)" << std::endl;
  EXPECT_NEAR(robot.state().positions[0], frozen_at, 1e-12);
}

TEST(ArmControllerSplice, FollowingTheMeasuredPoseFeelsNoPullAndHoldsWhereReleased)
{
  const std::vector<std::string> names = { "r_a", "r_b" };
  MeasuredRobot robot(names);
  robot.reset({ 0.1, 0.2 });
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(2));
  arm.update(0.0);
  robot.frozen = true;  // the operator moves it
  arm.followMeasured(true);
  for (int k = 1; k <= 100; ++k)
  {
    robot.push({ 0.1 + 0.003 * k, 0.2 - 0.002 * k });
    const auto c = arm.update(0.01 * k);
    EXPECT_EQ(robot.command().positions, robot.state().positions);
    EXPECT_EQ(c.desired.velocities, (std::vector<double>{ 0.0, 0.0 }));
  }
  arm.followMeasured(false);
  arm.holdMeasured();
  robot.frozen = false;
  for (int k = 101; k <= 300; ++k)
    arm.update(0.01 * k), robot.write(0.01 * k, 0.01);
  EXPECT_NEAR(robot.state().positions[0], 0.4, 1e-12);
  EXPECT_NEAR(robot.state().positions[1], 0.0, 1e-12);
}

TEST(ArmControllerSplice, AReleasedArmHoldsWhatTheReturningHardwareCommands)
{
  const std::vector<std::string> names = { "r_a" };
  MeasuredRobot robot(names);
  ArmController arm(robot, names, TrajectoryValidator(limits(names), {}), options(1));
  arm.start(arm.plan(ramp(names, 1.0, 1.0), 0.0, 0.0), noTolerances(1), 0.0);
  for (double t = 0.0; t < 0.5; t += 0.01)
    arm.update(t), robot.write(t, 0.01);
  arm.release();  // the states stopped; a restarted simulation reports its own pose
  robot.reset({ -0.25 });
  const auto c = arm.update(0.6);
  EXPECT_EQ(c.desired.positions[0], -0.25);
  EXPECT_FALSE(arm.moving());
}
