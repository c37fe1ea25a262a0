// Node test (rostest, real master, real Bullet physics): a scripted hand drags the free-driven UR5e's
// wrist 20 cm at 0.2 m/s; releasing with rigid drives freezes it; a ghost plan executes within tolerance.
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <vrrw_msgs/GhostExecute.h>
#include <vrrw_msgs/GhostPlan.h>
#include <vrrw_msgs/GhostPreset.h>

#include "../bench/hand_drag.h"
#include "interaction_fixture.h"

using namespace vrrw_interaction_test;

namespace
{
ros::NodeHandle* nh = nullptr;
tf2_ros::Buffer* tf = nullptr;
}  // namespace

TEST(InteractionPhysics, AHandDragsTheWristAndReleasingFreezesIt)
{
  const auto figures = vrrw_interaction_bench::dragWrist(*nh, *tf, 0.2, 0.2, 2.0);
  ASSERT_EQ(figures.error, "");
  std::cout << "grabbed " << figures.body << ": rms " << figures.rms << " m, max " << figures.max << " m over "
            << figures.samples << " samples; drift " << figures.drift << " m in 2 s\n";
  EXPECT_EQ(figures.body.rfind("ur5e_", 0), 0u);
  EXPECT_LT(figures.rms, 0.02);
  EXPECT_LT(figures.drift, 1e-3);
}

TEST(InteractionPhysics, AGhostPlanExecutesWithinTheGoalTolerance)
{
  Latest<sensor_msgs::JointState> robot(*nh, "/ur5e/joint_states");
  vrrw_msgs::GhostPreset preset;
  preset.request.name = "square_center";
  ASSERT_TRUE(call("/ur5e/ghost/preset", preset).response.success);
  vrrw_msgs::GhostPlan plan;
  plan = call("/ur5e/ghost/plan", plan);
  ASSERT_TRUE(plan.response.success) << plan.response.message;
  const auto execute = call<vrrw_msgs::GhostExecute>("/ur5e/ghost/execute");
  ASSERT_TRUE(execute.response.success) << execute.response.message << " " << execute.response.error_string;
  ros::WallDuration(0.2).sleep();
  const auto& goal = plan.response.trajectory.points.back().positions;
  const Eigen::VectorXd q = arm6(robot.last());
  for (int j = 0; j < 6; ++j)
    EXPECT_NEAR(q[j], goal[j], 0.01) << "joint " << j;
}

TEST(InteractionPhysics, AnOpenHandPushesTheDrill)
{
  const auto drillAt = []() -> Eigen::Vector3d {
    return tf2::transformToEigen(tf->lookupTransform("world", "drill", ros::Time(0), ros::Duration(2.0))).translation();
  };
  const Eigen::Vector3d start = drillAt();
  ros::Publisher pose_pub = nh->advertise<geometry_msgs::PoseStamped>("/operator/pusher/pose", 10);
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "world";
  pose.pose.orientation.w = 1.0;
  const Eigen::Vector3d from = start + Eigen::Vector3d(0, -0.15, 0.03);
  pose.pose.position = tf2::toMsg(from);
  for (int i = 0; i < 300 && pose_pub.getNumSubscribers() == 0; ++i, ros::WallDuration(0.01).sleep())
    pose_pub.publish(pose);  // the node finds new hands once a second
  ASSERT_GT(pose_pub.getNumSubscribers(), 0u);
  for (int i = 0; i <= 150; ++i, ros::WallDuration(0.01).sleep())  // open hand, 20 cm along +y in 1 s, then rest
  {
    pose.header.stamp = ros::Time::now();
    pose.pose.position = tf2::toMsg(Eigen::Vector3d(from + Eigen::Vector3d(0, 0.2 * std::min(1.0, i / 100.0), 0)));
    pose_pub.publish(pose);
  }
  const Eigen::Vector3d moved = drillAt() - start;
  std::cout << "drill pushed " << moved.transpose() << " m\n";
  EXPECT_GT(moved.y(), 0.02);
}

TEST(InteractionPhysics, TheMouseMarkerPullsTheTcp)
{
  std_srvs::SetBool on;
  on.request.data = true;
  ASSERT_TRUE(call("/ur5e/free_drive", on).response.success);
  const auto tcpAt = []() -> Eigen::Vector3d {
    return tf2::transformToEigen(tf->lookupTransform("world", "ur5e_tcp", ros::Time(0), ros::Duration(2.0))).translation();
  };
  ros::Publisher pub = nh->advertise<visualization_msgs::InteractiveMarkerFeedback>("/free_drive/feedback", 10);
  for (int i = 0; i < 300 && pub.getNumSubscribers() == 0; ++i)
    ros::WallDuration(0.01).sleep();
  const Eigen::Vector3d start = tcpAt();
  visualization_msgs::InteractiveMarkerFeedback f;
  f.header.frame_id = "world";
  f.client_id = "test";
  f.marker_name = "ur5e";
  f.pose.orientation.w = 1.0;
  using F = visualization_msgs::InteractiveMarkerFeedback;
  for (int i = 0; i <= 100; ++i, ros::WallDuration(0.01).sleep())  // down, 10 cm along -y in 0.5 s, hold
  {
    f.event_type = i == 0 ? F::MOUSE_DOWN : F::POSE_UPDATE;
    f.header.stamp = ros::Time::now();
    f.pose.position = tf2::toMsg(Eigen::Vector3d(start - Eigen::Vector3d(0, 0.1 * std::min(1.0, i / 50.0), 0)));
    pub.publish(f);
  }
  f.event_type = F::MOUSE_UP;
  pub.publish(f);
  const Eigen::Vector3d moved = tcpAt() - start;
  std::cout << "mouse pulled the TCP " << moved.transpose() << " m\n";
  EXPECT_NEAR(moved.y(), -0.1, 0.02);
  ASSERT_TRUE(call<std_srvs::SetBool>("/ur5e/free_drive").response.success);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_interaction_physics");
  ros::NodeHandle handle;
  nh = &handle;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  tf = &buffer;
  return RUN_ALL_TESTS();
}
