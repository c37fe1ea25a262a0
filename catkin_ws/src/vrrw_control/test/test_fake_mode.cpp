// Node test (rostest, real master): controller_node in fake mode for two robots, on simulated time that the
// test advances (test_clock.h): every control cycle happens and the test acts at simulated instants.
#include <vrrw_trajectory/msg_conversions.h>
#include <actionlib/client/simple_action_client.h>
#include <cmath>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include <limits>
#include "ros_test_helpers.h"
#include "test_clock.h"
#include <vrrw_control/ros/msg_conversions.h>
#include <vrrw_control/trajectory_interpolator.h>

using namespace vrrw_control_test;
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = actionlib::SimpleActionClient<control_msgs::GripperCommandAction>;
using Result = control_msgs::FollowJointTrajectoryResult;
using State = actionlib::SimpleClientGoalState;

namespace
{
const double kVelocityLimit = 3.14159265, kAccelerationLimit = 3.14159265;  // ur.xacro, urdf/config/ur5e.yaml
TestClock* sim = nullptr;

struct Robot
{
  Robot(ros::NodeHandle& nh, const std::string& name)
    : prefix(name + "_")
    , arm("/" + name + "/arm_controller/follow_joint_trajectory", false)
    , gripper("/" + name + "/gripper_controller/gripper_cmd", false)
    , states(nh, "/" + name + "/joint_states")
  {
    EXPECT_TRUE(waitForServer(*sim, arm));
    EXPECT_TRUE(waitForServer(*sim, gripper));
  }
  std::vector<double> arm_positions()
  {
    sensor_msgs::JointState s;
    EXPECT_TRUE(states.waitLatest(s));
    return std::vector<double>(s.position.begin(), s.position.begin() + 6);
  }
  std::string prefix;
  ArmClient arm;
  GripperClient gripper;
  JointStateLog states;
};

Robot* ur5e = nullptr;
Robot* ur3e = nullptr;

std::vector<double> armOf(const sensor_msgs::JointState& s) { return { s.position.begin(), s.position.begin() + 6 }; }
}  // namespace

namespace
{
/// Runs a 6-joint quintic trajectory and compares every published sample with the interpolant.
void reproduce(Robot& robot, double rate)
{
  const auto q0 = robot.arm_positions();
  control_msgs::FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = armJoints(robot.prefix);
  std::vector<double> q1(q0), q2(q0), v1(6), a1(6), zero(6, 0.0);
  for (size_t j = 0; j < 6; ++j)
  {
    q1[j] += 0.3 + 0.05 * j;
    q2[j] -= 0.2 * (j % 2 ? 1.0 : -1.0);
    v1[j] = 0.2 - 0.08 * j;
    a1[j] = 0.5 - 0.2 * j;
  }
  g.trajectory.points = { point(0.0, q0, zero, zero), point(0.8, q1, v1, a1), point(1.7, q2, zero, zero) };
  const ros::Time start = sim->now() + ros::Duration(0.3);
  g.trajectory.header.stamp = start;
  std::atomic<int> feedback{ 0 };
  robot.arm.sendGoal(g, ArmClient::SimpleDoneCallback(), ArmClient::SimpleActiveCallback(),
                     [&](const control_msgs::FollowJointTrajectoryFeedbackConstPtr&) { ++feedback; });
  ASSERT_TRUE(waitTaken(robot.arm));
  ASSERT_TRUE(sim->advanceUntilDone(robot.arm, 10.0));
  EXPECT_EQ(robot.arm.getState(), State::SUCCEEDED);
  EXPECT_EQ(robot.arm.getResult()->error_code, Result::SUCCESSFUL);
  sim->advance(0.1);

  const vrrw_control::TrajectoryInterpolator reference(vrrw_trajectory::fromMsg(g.trajectory));
  const auto run = robot.states.since(start - ros::Duration(0.1));
  double max_error = 0.0;
  size_t during = 0;
  for (const auto& s : run)
  {
    const double t = (s.header.stamp - start).toSec();
    const auto expected = reference.sample(t);
    during += t >= 0.0 && t <= 1.7;
    for (size_t j = 0; j < 6; ++j)
      max_error = std::max(max_error, std::abs(s.position[j] - expected.positions[j]));
  }
  std::cout << robot.prefix << " fake reproduction at " << rate << " Hz: " << during
            << " samples in the 1.7 s motion, max |q - interpolant| = " << max_error
            << " rad, feedback messages " << feedback.load() << std::endl;
  EXPECT_LT(max_error, 1e-14);  // 1.8e-15 measured on both robots (rounding: the same interpolant, target 1e-9)
  // One joint_states and one feedback per control cycle: the test's clock waits for every cycle, so none is
  // lost however loaded the machine (on the wall clock 73 % of a 1 kHz loop's cycles were kept at load 7).
  EXPECT_GE(during, static_cast<size_t>(rate * 1.7));
  EXPECT_GE(feedback.load(), static_cast<int>(rate * 1.7));
}
}  // namespace

TEST(FakeMode, ReproducesTheInterpolantAtEveryPublishedSample)
{
  reproduce(*ur5e, 100.0);
  reproduce(*ur3e, 1000.0);
}

TEST(FakeMode, EveryValidationRuleRejectsAndLeavesTheRobotWhereItWas)
{
  const auto q0 = ur5e->arm_positions();
  const auto good = move("ur5e_", q0, { 0.2, 0.2, 0.2, 0.2, 0.2, 0.2 }, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case
  {
    std::string rule;
    std::function<void(control_msgs::FollowJointTrajectoryGoal&)> spoil;
    int code;
    std::string expect;
  };
  const std::vector<Case> cases = {
    { "duplicate joint", [](auto& g) { g.trajectory.joint_names[1] = "ur5e_shoulder_pan_joint"; },
      Result::INVALID_JOINTS, "joint ur5e_shoulder_pan_joint: named twice" },
    { "foreign joint", [](auto& g) { g.trajectory.joint_names[2] = "ur3e_elbow_joint"; }, Result::INVALID_JOINTS,
      "joint ur3e_elbow_joint: not a joint of this controller" },
    { "missing joint",
      [](auto& g) {
        g.trajectory.joint_names.pop_back();
        for (auto& p : g.trajectory.points)
          p.positions.pop_back(), p.velocities.pop_back();
      },
      Result::INVALID_JOINTS, "joint ur5e_wrist_3_joint: missing" },
    { "time not increasing", [](auto& g) { g.trajectory.points[1].time_from_start = ros::Duration(0.0); },
      Result::INVALID_GOAL, "point 1: time_from_start 0 s does not increase" },
    { "not finite", [&](auto& g) { g.trajectory.points[1].positions[3] = nan; }, Result::INVALID_GOAL,
      "point 1: joint ur5e_wrist_1_joint: value is not finite" },
    { "position limit", [](auto& g) { g.trajectory.points[1].positions[2] = 3.5; }, Result::INVALID_GOAL,
      "point 1: joint ur5e_elbow_joint: position 3.5 outside limits" },
    { "velocity limit", [](auto& g) { g.trajectory.points[1].velocities[4] = 4.0; }, Result::INVALID_GOAL,
      "point 1: joint ur5e_wrist_2_joint: velocity 4 exceeds limit 3.14159" },
    { "acceleration limit",
      [](auto& g) {
        for (auto& p : g.trajectory.points)
          p.accelerations.assign(6, 0.0);
        g.trajectory.points[1].accelerations[0] = 4.0;
      },
      Result::INVALID_GOAL, "point 1: joint ur5e_shoulder_pan_joint: acceleration 4 exceeds limit 3.14159" },
    { "interpolated velocity", [](auto& g) { g.trajectory.points[1].time_from_start = ros::Duration(0.05); },
      Result::INVALID_GOAL, "point 1: joint ur5e_shoulder_pan_joint: interpolated velocity" },
    { "start tolerance", [](auto& g) { g.trajectory.points[0].positions[5] += 0.5; }, Result::INVALID_GOAL,
      "point 0: joint ur5e_wrist_3_joint: starts 0.5 from the current position" },
    { "old header", [](auto& g) { g.trajectory.header.stamp = sim->now() - ros::Duration(5.0); },
      Result::OLD_HEADER_TIMESTAMP, "in the past" },
  };
  for (const auto& c : cases)
  {
    auto g = good;
    c.spoil(g);
    sensor_msgs::JointState before;
    ASSERT_TRUE(ur5e->states.waitLatest(before));
    ur5e->arm.sendGoal(g);
    ASSERT_TRUE(sim->advanceUntilDone(ur5e->arm, 5.0)) << c.rule;
    EXPECT_EQ(ur5e->arm.getState(), State::REJECTED) << c.rule;
    EXPECT_EQ(ur5e->arm.getResult()->error_code, c.code) << c.rule;
    EXPECT_NE(ur5e->arm.getResult()->error_string.find(c.expect), std::string::npos)
        << c.rule << ": " << ur5e->arm.getResult()->error_string;
    sim->advance(0.02);  // two cycles of the UR5e
    sensor_msgs::JointState after;
    ASSERT_TRUE(ur5e->states.waitLatest(after));
    EXPECT_GT(after.header.stamp, before.header.stamp);
    EXPECT_EQ(after.position, before.position) << c.rule << ": the robot moved";
  }
}

TEST(FakeMode, CancelStopsSmoothly)
{
  const auto q0 = ur5e->arm_positions();
  ur5e->arm.sendGoal(move("ur5e_", q0, { 1.5, -1.0, 0.5, 0.0, 0.0, 1.5 }, 2.5));
  const ros::Time start = sim->now();
  ASSERT_TRUE(waitTaken(ur5e->arm));
  sim->advance(1.2);  // near peak velocity 0.9 rad/s
  ur5e->arm.cancelGoal();
  ASSERT_TRUE(sim->advanceUntilDone(ur5e->arm, 5.0));
  EXPECT_EQ(ur5e->arm.getState(), State::PREEMPTED);
  sim->advance(0.6);
  const auto run = ur5e->states.since(start);
  double vmax, amax;
  finiteDifferences(run, vmax, amax);
  std::cout << "cancel: max |qd| " << vmax << " rad/s, max |qdd| " << amax << " rad/s^2" << std::endl;
  EXPECT_LE(vmax, 1.5 * 1.5 / 2.5 + 1e-6);  // never faster than the trajectory's own peak
  EXPECT_LE(amax, kAccelerationLimit * 1.05);
  const auto last = armOf(run.back()), before_last = armOf(run[run.size() - 5]);
  EXPECT_EQ(last, before_last) << "still moving after the stop";
  EXPECT_LT(last[0], q0[0] + 1.5 - 0.1) << "the stop did not end early";
}

TEST(FakeMode, ANewGoalSplicesIntoTheRunningOneWithoutAStep)
{
  ArmClient second("/ur3e/arm_controller/follow_joint_trajectory", true);  // connected before the motion starts
  ASSERT_TRUE(waitForServer(*sim, second));
  const auto q0 = ur3e->arm_positions();
  ur3e->arm.sendGoal(move("ur3e_", q0, { 1.0, 1.0, -1.0, 0.5, 0.5, 0.5 }, 2.0));
  const ros::Time start = sim->now();
  ASSERT_TRUE(waitTaken(ur3e->arm));
  sim->advance(1.0);
  // back to q0 from a trajectory planned there: its first point has passed and is dropped, the splice
  // runs from the current desired state, stretched to the limits (0.5 s would break them)
  auto back = move("ur3e_", q0, { 0, 0, 0, 0, 0, 0 }, 0.5);
  second.sendGoal(back);
  ASSERT_TRUE(waitTaken(second));
  ASSERT_TRUE(sim->advanceUntilDone(second, 15.0));
  EXPECT_EQ(second.getState(), State::SUCCEEDED) << second.getResult()->error_string;
  ASSERT_TRUE(sim->advanceUntilDone(ur3e->arm, 1.0));
  EXPECT_EQ(ur3e->arm.getState(), State::PREEMPTED);
  sim->advance(0.1);
  const auto run = ur3e->states.since(start);
  expectWithinLimits(run, "splice through the action", kVelocityLimit, kAccelerationLimit);
  const auto last = armOf(run.back());
  for (size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(last[j], q0[j], 1e-9);
}

TEST(FakeMode, TwoRobotsMoveAtOnceWithoutInterfering)
{
  const auto a0 = ur5e->arm_positions(), b0 = ur3e->arm_positions();
  ur5e->arm.sendGoal(move("ur5e_", a0, { 0.3, 0, 0, 0, 0, 0 }, 1.0));
  ur3e->arm.sendGoal(move("ur3e_", b0, { 0, 0, 0, 0, 0, -0.4 }, 1.0));
  ASSERT_TRUE(sim->advanceUntil([] { return ur5e->arm.getState().isDone() && ur3e->arm.getState().isDone(); }, 5.0));
  EXPECT_EQ(ur5e->arm.getState(), State::SUCCEEDED);
  EXPECT_EQ(ur3e->arm.getState(), State::SUCCEEDED);
  sim->advance(0.05);
  const auto a1 = ur5e->arm_positions(), b1 = ur3e->arm_positions();
  EXPECT_NEAR(a1[0] - a0[0], 0.3, 1e-12);
  EXPECT_NEAR(b1[5] - b0[5], -0.4, 1e-12);
  EXPECT_EQ(a1[5], a0[5]);
  EXPECT_EQ(b1[0], b0[0]);
}

TEST(FakeMode, GripperReachesGoalAndRejectsOutOfRange)
{
  control_msgs::GripperCommandGoal g;
  g.command.position = 0.5;
  g.command.max_effort = 20.0;
  ur5e->gripper.sendGoal(g);
  ASSERT_TRUE(sim->advanceUntilDone(ur5e->gripper, 5.0));
  EXPECT_EQ(ur5e->gripper.getState(), State::SUCCEEDED);
  EXPECT_TRUE(ur5e->gripper.getResult()->reached_goal);
  EXPECT_FALSE(ur5e->gripper.getResult()->stalled);
  EXPECT_NEAR(ur5e->gripper.getResult()->position, 0.5, 0.01);
  g.command.position = 0.95;
  ur5e->gripper.sendGoal(g);
  ASSERT_TRUE(sim->advanceUntilDone(ur5e->gripper, 5.0));
  EXPECT_EQ(ur5e->gripper.getState(), State::REJECTED);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_fake_mode");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  TestClock clock(nh, ros::Time(100.0));  // the controllers start at its first tick
  sim = &clock;
  Robot a(nh, "ur5e"), b(nh, "ur3e");
  clock.follow(a.states, 0.01);   // fake_mode.test: 100 Hz
  clock.follow(b.states, 0.001);  // 1 kHz
  clock.advance(0.1);             // the first states
  ur5e = &a;
  ur3e = &b;
  return RUN_ALL_TESTS();
}
