// Node test (rostest, real master): physics mode with vrrw_physics' physics_node. The gripper
// closes on a fixed block between its fingers and reports stalled; opening reaches its goal.
#include <actionlib/client/simple_action_client.h>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

using GripperClient = actionlib::SimpleActionClient<control_msgs::GripperCommandAction>;
using State = actionlib::SimpleClientGoalState;

TEST(PhysicsGrasp, ClosingOnABlockStallsOpeningReachesTheGoal)
{
  GripperClient gripper("/ur5e/gripper_controller/gripper_cmd", true);
  ASSERT_TRUE(gripper.waitForServer(ros::Duration(20.0)));
  ros::Duration(0.5).sleep();
  control_msgs::GripperCommandGoal g;
  g.command.position = 0.8;  // fully closed without the block
  g.command.max_effort = 50.0;
  gripper.sendGoal(g);
  ASSERT_TRUE(gripper.waitForResult(ros::Duration(10.0)));
  const auto closed = *gripper.getResult();
  std::cout << "close on block: state " << gripper.getState().toString() << ", position " << closed.position
            << ", stalled " << int(closed.stalled) << ", reached_goal " << int(closed.reached_goal) << std::endl;
  EXPECT_EQ(gripper.getState(), State::SUCCEEDED);
  EXPECT_TRUE(closed.stalled);
  EXPECT_FALSE(closed.reached_goal);
  EXPECT_GT(closed.position, 0.1);
  EXPECT_LT(closed.position, 0.7);

  g.command.position = 0.1;  // away from the joint's stop at 0
  gripper.sendGoal(g);
  ASSERT_TRUE(gripper.waitForResult(ros::Duration(10.0)));
  std::cout << "open: position " << gripper.getResult()->position << std::endl;
  EXPECT_EQ(gripper.getState(), State::SUCCEEDED);
  EXPECT_TRUE(gripper.getResult()->reached_goal);
  EXPECT_FALSE(gripper.getResult()->stalled);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_grasp");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
