// md5sums published for ros-controls/control_msgs 1.5 (rosserial/roslisp generated headers,
// docs.ros.org message pages); equality means a real driver accepts our messages unchanged.
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include <ros/message_traits.h>

template <class M>
std::string md5()
{
  return ros::message_traits::MD5Sum<M>::value();
}

template <class M>
std::string type()
{
  return ros::message_traits::DataType<M>::value();
}

TEST(ControlMsgs, JointToleranceAndGripperCommand)
{
  EXPECT_EQ(md5<control_msgs::JointTolerance>(), "f544fe9c16cf04547e135dd6063ff5be");
  EXPECT_EQ(md5<control_msgs::GripperCommand>(), "680acaff79486f017132a7f198d40f08");
  EXPECT_EQ(type<control_msgs::GripperCommand>(), "control_msgs/GripperCommand");
}

TEST(ControlMsgs, FollowJointTrajectory)
{
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryGoal>(), "69636787b6ecbde4d61d711979bc7ecb");
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryActionGoal>(), "cff5c1d533bf2f82dd0138d57f4304bb");
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryResult>(), "493383b18409bfb604b4e26c676401d2");
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryActionResult>(), "c4fb3b000dc9da4fd99699380efcc5d9");
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryFeedback>(), "10817c60c2486ef6b33e97dcd87f4474");
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryActionFeedback>(), "d8920dc4eae9fc107e00999cce4be641");
  EXPECT_EQ(md5<control_msgs::FollowJointTrajectoryAction>(), "bc4f9b743838566551c0390c65f1a248");
  EXPECT_EQ(type<control_msgs::FollowJointTrajectoryActionGoal>(), "control_msgs/FollowJointTrajectoryActionGoal");
}

TEST(ControlMsgs, GripperCommand)
{
  EXPECT_EQ(md5<control_msgs::GripperCommandGoal>(), "86fd82f4ddc48a4cb6856cfa69217e43");
  EXPECT_EQ(md5<control_msgs::GripperCommandResult>(), "e4cbff56d3562bcf113da5a5adeef91f");
  EXPECT_EQ(md5<control_msgs::GripperCommandFeedback>(), "e4cbff56d3562bcf113da5a5adeef91f");
  EXPECT_EQ(md5<control_msgs::GripperCommandAction>(), "950b2a6ebe831f5d4f4ceaba3d8be01e");
}

TEST(ControlMsgs, ResultCodes)
{
  using R = control_msgs::FollowJointTrajectoryResult;
  EXPECT_EQ(R::SUCCESSFUL, 0);
  EXPECT_EQ(R::INVALID_GOAL, -1);
  EXPECT_EQ(R::INVALID_JOINTS, -2);
  EXPECT_EQ(R::OLD_HEADER_TIMESTAMP, -3);
  EXPECT_EQ(R::PATH_TOLERANCE_VIOLATED, -4);
  EXPECT_EQ(R::GOAL_TOLERANCE_VIOLATED, -5);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
