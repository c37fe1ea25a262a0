// Node test (rostest, real master): physics mode against a stand-in drive model. Checks the
// PhysicsRobot streaming path, path/goal/goal-time tolerances with their error codes and the
// gripper stall report. A joint blocked at 0.25 rad (wrist_2) and the finger blocked at 0.35 rad
// play objects in the way.
#include <actionlib/client/simple_action_client.h>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include "ros_test_helpers.h"

using namespace vrrw_control_test;
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = actionlib::SimpleActionClient<control_msgs::GripperCommandAction>;
using Result = control_msgs::FollowJointTrajectoryResult;
using State = actionlib::SimpleClientGoalState;

namespace
{
ArmClient* arm = nullptr;
GripperClient* gripper = nullptr;
JointStateLog* states = nullptr;

std::vector<double> armNow()
{
  sensor_msgs::JointState s;
  EXPECT_TRUE(states->waitLatest(s));
  return { s.position.begin(), s.position.begin() + 6 };
}

control_msgs::JointTolerance tolerance(const std::string& joint, double position)
{
  control_msgs::JointTolerance t;
  t.name = joint;
  t.position = position;
  return t;
}
}  // namespace

TEST(PhysicsStandIn, HoldsTheInitialPoseOfThePhysicsRobot)
{
  ros::Duration(0.3).sleep();
  const auto q = armNow();
  EXPECT_NEAR(q[1], -1.2, 1e-3);
  EXPECT_NEAR(q[2], 1.0, 1e-3);
}

TEST(PhysicsStandIn, TracksAndSucceeds)
{
  double max_error = 0.0;
  arm->sendGoal(move("ur5e_", armNow(), { 0.3, -0.3, 0.3, 0.3, 0.1, 0.3 }, 1.5), ArmClient::SimpleDoneCallback(),
                ArmClient::SimpleActiveCallback(), [&](const control_msgs::FollowJointTrajectoryFeedbackConstPtr& f) {
                  for (double e : f->error.positions)
                    max_error = std::max(max_error, std::abs(e));
                });
  ASSERT_TRUE(arm->waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(arm->getState(), State::SUCCEEDED) << arm->getResult()->error_string;
  std::cout << "stand-in tracking: max |desired - actual| from feedback " << max_error << " rad" << std::endl;
  EXPECT_GT(max_error, 0.0);  // actual comes from the drive model, not from the command
  EXPECT_LT(max_error, 0.05);
}

TEST(PhysicsStandIn, PathToleranceViolationAbortsAndStops)
{
  auto g = move("ur5e_", armNow(), { -0.4, 0, 0, 0, 0, 0 }, 1.0);
  g.path_tolerance = { tolerance("ur5e_shoulder_pan_joint", 1e-4) };
  arm->sendGoal(g);
  ASSERT_TRUE(arm->waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(arm->getState(), State::ABORTED);
  EXPECT_EQ(arm->getResult()->error_code, Result::PATH_TOLERANCE_VIOLATED);
  EXPECT_NE(arm->getResult()->error_string.find("joint ur5e_shoulder_pan_joint: position error"), std::string::npos)
      << arm->getResult()->error_string;
  ros::Duration(1.0).sleep();
  sensor_msgs::JointState s;
  ASSERT_TRUE(states->waitLatest(s));
  EXPECT_LT(std::abs(s.velocity[0]), 1e-3) << "not at rest after the stop";
}

TEST(PhysicsStandIn, GoalToleranceAfterGoalTimeAborts)
{
  auto g = move("ur5e_", armNow(), { 0, 0, 0, 0, 0.3, 0 }, 0.6);  // wrist_2 blocked at 0.25
  g.goal_time_tolerance = ros::Duration(0.4);
  const ros::Time start = ros::Time::now();
  arm->sendGoal(g);
  ASSERT_TRUE(arm->waitForResult(ros::Duration(10.0)));
  const double elapsed = (ros::Time::now() - start).toSec();
  EXPECT_EQ(arm->getState(), State::ABORTED);
  EXPECT_EQ(arm->getResult()->error_code, Result::GOAL_TOLERANCE_VIOLATED);
  EXPECT_NE(arm->getResult()->error_string.find("joint ur5e_wrist_2_joint"), std::string::npos)
      << arm->getResult()->error_string;
  EXPECT_NEAR(elapsed, 1.0, 0.15);
}

TEST(PhysicsStandIn, GripperReportsStallOnAnObject)
{
  control_msgs::GripperCommandGoal g;
  g.command.position = 0.2;
  gripper->sendGoal(g);
  ASSERT_TRUE(gripper->waitForResult(ros::Duration(5.0)));
  EXPECT_TRUE(gripper->getResult()->reached_goal);
  EXPECT_FALSE(gripper->getResult()->stalled);

  g.command.position = 0.7;
  gripper->sendGoal(g);
  ASSERT_TRUE(gripper->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(gripper->getState(), State::SUCCEEDED);
  EXPECT_TRUE(gripper->getResult()->stalled);
  EXPECT_FALSE(gripper->getResult()->reached_goal);
  EXPECT_NEAR(gripper->getResult()->position, 0.35, 1e-6);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_stand_in");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ArmClient a("/ur5e/arm_controller/follow_joint_trajectory", false);
  GripperClient g("/ur5e/gripper_controller/gripper_cmd", false);
  JointStateLog s(nh, "/ur5e/joint_states");
  arm = &a;
  gripper = &g;
  states = &s;
  if (!a.waitForServer(ros::Duration(15.0)) || !g.waitForServer(ros::Duration(15.0)))
    return 1;
  ros::Duration(0.5).sleep();
  return RUN_ALL_TESTS();
}
