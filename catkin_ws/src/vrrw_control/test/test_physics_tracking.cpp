// Node test (rostest, real master): physics mode with vrrw_physics' physics_node. A pick motion
// (approach, descend, close the gripper, lift) is tracked within 2e-3 rad with rigid gains,
// measured at every joint_states sample of the physics node against the interpolant at its stamp.
#include <actionlib/client/simple_action_client.h>
#include <cmath>
#include <control_msgs/GripperCommandAction.h>
#include <gtest/gtest.h>
#include "ros_test_helpers.h"
#include <vrrw_control/msg_conversions.h>
#include <vrrw_control/trajectory_interpolator.h>

using namespace vrrw_control_test;
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using State = actionlib::SimpleClientGoalState;

TEST(PhysicsTracking, PickMotionWithinTwoMilliradians)
{
  ros::NodeHandle nh;
  ArmClient arm("/ur5e/arm_controller/follow_joint_trajectory", true);
  ASSERT_TRUE(arm.waitForServer(ros::Duration(20.0)));
  JointStateLog states(nh, "/ur5e/joint_states");
  sensor_msgs::JointState s;
  ASSERT_TRUE(states.waitLatest(s, 10.0));
  ros::Duration(1.0).sleep();  // settle under gravity
  ASSERT_TRUE(states.waitLatest(s));
  std::vector<double> q0(s.position.begin(), s.position.begin() + 6);

  const std::vector<double> zero(6, 0.0);
  std::vector<double> pre(q0), grasp(q0);
  const double approach[6] = { 0.5, 0.35, -0.45, 0.3, 0.0, 0.6 }, descend[6] = { 0.0, 0.15, -0.12, -0.05, 0.0, 0.0 };
  for (size_t j = 0; j < 6; ++j)
  {
    pre[j] += approach[j];
    grasp[j] = pre[j] + descend[j];
  }
  control_msgs::FollowJointTrajectoryGoal g;
  g.trajectory.joint_names = armJoints("ur5e_");
  g.trajectory.points = { point(0.0, q0, zero), point(2.0, pre, zero), point(3.0, grasp, zero),
                          point(3.6, grasp, zero), point(4.6, pre, zero) };
  const ros::Time start = ros::Time::now() + ros::Duration(0.3);
  g.trajectory.header.stamp = start;
  arm.sendGoal(g);
  ASSERT_TRUE(arm.waitForResult(ros::Duration(15.0)));
  EXPECT_EQ(arm.getState(), State::SUCCEEDED) << arm.getResult()->error_string;
  ros::Duration(0.3).sleep();

  const vrrw_control::TrajectoryInterpolator reference(vrrw_control::fromMsg(g.trajectory));
  double max_error = 0.0, sum_sq = 0.0, worst_t = 0.0, worst_v = 0.0;
  size_t n = 0, worst_joint = 0;
  for (const auto& m : states.since(start))
  {
    const double t = (m.header.stamp - start).toSec();
    if (t > 4.9)
      break;
    const auto d = reference.sample(t);
    for (size_t j = 0; j < 6; ++j)
    {
      const double e = std::abs(m.position[j] - d.positions[j]);
      if (e > max_error)
        max_error = e, worst_t = t, worst_joint = j, worst_v = d.velocities[j];
      sum_sq += e * e;
    }
    ++n;
  }
  const double rms = std::sqrt(sum_sq / std::max<size_t>(1, 6 * n));
  std::cout << "physics tracking: " << n << " samples, max |q - interpolant| " << max_error << " rad, rms " << rms
            << " rad (joint " << worst_joint << " at t = " << worst_t << " s, desired velocity " << worst_v << " rad/s)"
            << std::endl;
  RecordProperty("max_error_rad", std::to_string(max_error));
  EXPECT_GT(n, 1000u);
  EXPECT_LT(max_error, 2e-3);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_tracking");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
