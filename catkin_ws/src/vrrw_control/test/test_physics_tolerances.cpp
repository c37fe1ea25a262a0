// Node test (rostest, real master): path and goal tolerances of a measured arm, the controller inside the
// physics node in lockstep and the test stepping simulated time, so when a goal ends is exact. The UR5e of
// pick_place_drill runs compliant (no stiffness: its position drifts behind the motion) or nearly free to break
// its tolerances; rigid, a motion succeeds.
#include <vrrw_common/ros/action_client.h>
#include <gtest/gtest.h>
#include <vrrw_physics/SetGains.h>
#include <vrrw_physics/SetMode.h>

#include "lockstep_client.h"

using namespace vrrw_control_test;
using ArmClient = vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction>;
using Result = control_msgs::FollowJointTrajectoryResult;
using State = actionlib::SimpleClientGoalState;

namespace
{
ArmClient* arm = nullptr;
JointStateLog* states = nullptr;
Lockstep* sim = nullptr;

std::vector<double> armAt(const ros::Time& t)
{
  for (int i = 0; i < 500; ++i, ros::WallDuration(0.01).sleep())
  {
    sensor_msgs::JointState s;
    if (states->waitLatest(s) && s.header.stamp == t)
      return { s.position.begin(), s.position.begin() + 6 };
  }
  ADD_FAILURE() << "no joint_states of " << t;
  return std::vector<double>(6, 0.0);
}

void setDrives(const std::string& mode)
{
  vrrw_physics::SetMode srv;
  srv.request.robot = "ur5e";
  srv.request.mode = mode;
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_mode", srv) && srv.response.success) << srv.response.message;
}

/// Nearly free arm joints (no stiffness, 1 N m s/rad of damping): the arm hardly follows its targets.
void loosen()
{
  vrrw_physics::SetGains srv;
  srv.request.robot = "ur5e";
  srv.request.stiffness.assign(6, 0.0);
  srv.request.damping.assign(6, 1.0);
  ASSERT_TRUE(vrrw_common::services().tryCall("/physics/set_gains", srv) && srv.response.success) << srv.response.message;
}

/// Sends `goal` stamped now while the simulation waits, steps until the controller is idle; the time then.
ros::Time run(control_msgs::FollowJointTrajectoryGoal goal, ros::Time& start)
{
  start = sim->now();
  goal.trajectory.header.stamp = start;
  arm->sendGoal(goal);
  EXPECT_TRUE(waitAccepted(*arm));
  const ros::Time end = sim->step(20.0, true);
  EXPECT_TRUE(arm->waitForResult(ros::Duration(10.0)));
  return end;
}

control_msgs::JointTolerance tolerance(const std::string& joint, double position)
{
  control_msgs::JointTolerance t;
  t.name = joint;
  t.position = position;
  return t;
}
}  // namespace

TEST(PhysicsTolerances, RigidTracksAndSucceeds)
{
  ros::Time start;
  const ros::Time end = run(move("ur5e_", armAt(sim->now()), { 0.3, -0.2, 0.2, 0.2, 0.1, 0.3 }, 1.5), start);
  EXPECT_EQ(arm->getState(), State::SUCCEEDED) << arm->getResult()->error_string;
  std::cout << "rigid: succeeded " << (end - start).toSec() << " s after the start of a 1.5 s motion" << std::endl;
  EXPECT_NEAR((end - start).toSec(), 1.502, 0.003);  // lockstep: 1.502 s measured
}

TEST(PhysicsTolerances, PathToleranceViolationAbortsAndHoldsTheMeasuredPose)
{
  setDrives("compliant");
  auto goal = move("ur5e_", armAt(sim->now()), { -0.4, 0, 0, 0, 0, 0 }, 1.0);
  goal.path_tolerance = { tolerance("ur5e_shoulder_pan_joint", 1e-3) };
  ros::Time start;
  const ros::Time end = run(goal, start);
  EXPECT_EQ(arm->getState(), State::ABORTED);
  EXPECT_EQ(arm->getResult()->error_code, Result::PATH_TOLERANCE_VIOLATED);
  const std::string why = arm->getResult()->error_string;
  EXPECT_EQ(why.rfind("joint ur5e_shoulder_pan_joint: position error", 0), 0u) << why;
  EXPECT_NE(why.find("(path tolerance); a slower time profile, a larger path_tolerance"), std::string::npos) << why;
  std::cout << "compliant: path tolerance 1 mrad broken " << (end - start).toSec() << " s into the motion" << std::endl;
  EXPECT_NEAR((end - start).toSec(), 0.038, 0.005);  // lockstep: 0.038 s measured
  setDrives("rigid");
  const auto held = armAt(sim->step(0.01));
  const auto later = armAt(sim->step(1.0));
  for (size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(later[j], held[j], 1e-4) << "joint " << j << " moves on after the abort";
}

TEST(PhysicsTolerances, GoalToleranceAbortsExactlyGoalTimeAfterTheEnd)
{
  loosen();
  auto goal = move("ur5e_", armAt(sim->now()), { 0.4, 0, 0, 0, 0, 0 }, 0.6);
  goal.goal_time_tolerance = ros::Duration(0.4);
  ros::Time start;
  const ros::Time end = run(goal, start);
  setDrives("rigid");
  EXPECT_EQ(arm->getState(), State::ABORTED);
  EXPECT_EQ(arm->getResult()->error_code, Result::GOAL_TOLERANCE_VIOLATED);
  const std::string why = arm->getResult()->error_string;
  EXPECT_NE(why.find("joint ur5e_shoulder_pan_joint"), std::string::npos) << why;
  EXPECT_NE(why.find("(goal tolerance) 0.400000 s after the end; a slower time profile, a larger goal_tolerance"),
            std::string::npos)
      << why;
  std::cout << "compliant: goal tolerance aborted " << (end - start).toSec()
            << " s of simulated time after the start (0.6 s motion + 0.4 s goal_time)" << std::endl;
  EXPECT_NEAR((end - start).toSec(), 1.0, 0.0025);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_tolerances");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ArmClient a("/ur5e/arm_controller/follow_joint_trajectory");
  JointStateLog s(nh, "/ur5e/joint_states");
  Lockstep l;
  arm = &a;
  states = &s;
  sim = &l;
  if (!l.waitForPhysics() || !a.waitForServer(ros::Duration(30.0)))
    return 1;
  l.step(0.5);
  return RUN_ALL_TESTS();
}
