// Node test (rostest, real master, real Bullet physics, tf of the real URDF): the operator interfaces
// in physics mode. Free-drive: an operator spring pushes the compliant UR5e, the controller streams the
// measured pose with zero velocity; after free-drive the TCP holds within 1 mm for 5 s. Stale states: a
// paused physics node stops joint_states; the running goal aborts, new goals are rejected, and the arm
// holds where it was instead of moving on to the aborted goal's end.
#include <actionlib/client/simple_action_client.h>
#include <gtest/gtest.h>
#include <std_msgs/Bool.h>
#include <std_srvs/Trigger.h>
#include <vrrw_common/ros/persistent_service.h>
#include <tf2_ros/transform_listener.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetSpring.h>

#include "ros_test_helpers.h"

using namespace vrrw_control_test;
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using State = actionlib::SimpleClientGoalState;

namespace
{
struct Cell
{
  explicit Cell(ros::NodeHandle& nh)
    : arm("/ur5e/arm_controller/follow_joint_trajectory", true)
    , states(nh, "/ur5e/joint_states")
    , targets(nh, "/ur5e/drive_targets")
    , free_drive(nh.advertise<std_msgs::Bool>("/ur5e/free_drive_active", 1, true))
    , listener(tf)
  {
  }
  std::vector<double> q()
  {
    sensor_msgs::JointState s;
    EXPECT_TRUE(states.waitLatest(s));
    return { s.position.begin(), s.position.begin() + 6 };
  }
  /// The TCP's position in the world at the newest tf.
  tf2::Vector3 tcp()
  {
    const auto t = tf.lookupTransform("world", "ur5e_tcp", ros::Time(0), ros::Duration(2.0)).transform.translation;
    return { t.x, t.y, t.z };
  }
  void setFreeDrive(bool on)
  {
    std_msgs::Bool msg;
    msg.data = on;
    free_drive.publish(msg);
  }
  ArmClient arm;
  JointStateLog states, targets;
  ros::Publisher free_drive;
  tf2_ros::Buffer tf;
  tf2_ros::TransformListener listener;
};

Cell* cell = nullptr;

template <class Service>
void call(const std::string& name, Service& srv)
{
  ASSERT_TRUE(ros::service::waitForService(name, ros::Duration(10.0))) << name;
  ASSERT_TRUE(vrrw_common::services().tryCall(name, srv)) << name;
  ASSERT_TRUE(srv.response.success) << name << ": " << srv.response.message;
}

void setDrives(const std::string& mode)
{
  vrrw_physics::SetMode srv;
  srv.request.robot = "ur5e";
  srv.request.mode = mode;
  call("/physics/set_mode", srv);
}
}  // namespace

TEST(PhysicsOperator, APushedCompliantArmHoldsItsPoseAfterFreeDrive)
{
  const tf2::Vector3 before = cell->tcp();
  cell->setFreeDrive(true);
  setDrives("compliant");
  const ros::Time pushed = ros::Time::now();
  vrrw_physics::SetSpring hand;
  hand.request.id = "hand";
  hand.request.body = "ur5e_wrist_3_link";
  const auto wrist = cell->tf.lookupTransform("world", "ur5e_wrist_3_link", ros::Time(0), ros::Duration(2.0));
  hand.request.target.position.x = wrist.transform.translation.x + 0.15;
  hand.request.target.position.y = wrist.transform.translation.y;
  hand.request.target.position.z = wrist.transform.translation.z - 0.05;
  hand.request.target.orientation.w = 1.0;
  hand.request.stiffness = 400.0;
  hand.request.damping = 40.0;
  call("/physics/set_spring", hand);
  ros::Duration(1.5).sleep();
  hand.request.release = true;
  call("/physics/set_spring", hand);
  ros::Duration(0.3).sleep();
  const double moved = (cell->tcp() - before).length();

  // while free-drive is on the drive targets are the measured pose at rest: no pull anywhere
  double worst_offset = 0.0, worst_velocity = 0.0;
  const auto measured = cell->states.since(pushed);
  for (const auto& target : cell->targets.since(pushed + ros::Duration(0.1)))
  {
    const auto earlier = [](const sensor_msgs::JointState& m, const ros::Time& t) { return m.header.stamp < t; };
    const auto after = std::lower_bound(measured.begin(), measured.end(), target.header.stamp, earlier);
    if (after == measured.begin() || after == measured.end())
      continue;
    const auto& state = *(after - 1);  // the newest state the controller could have read
    for (size_t j = 0; j < 6; ++j)
    {
      worst_offset = std::max(worst_offset, std::abs(target.position[j] - state.position[j]));
      worst_velocity = std::max(worst_velocity, std::abs(target.velocity[j]));
    }
  }

  setDrives("rigid");  // first rigid (the targets still follow the arm), then free-drive off
  cell->setFreeDrive(false);
  ros::Duration(0.05).sleep();
  const tf2::Vector3 held = cell->tcp();
  double drift = 0.0;
  for (const ros::Time end = ros::Time::now() + ros::Duration(5.0); ros::Time::now() < end;)
  {
    ros::Duration(0.05).sleep();
    drift = std::max(drift, (cell->tcp() - held).length());
  }
  std::cout << "free-drive: the spring moved the TCP " << moved << " m; drive targets within " << worst_offset
            << " rad of the measured pose, |velocity| <= " << worst_velocity << " rad/s; after free-drive the TCP drifted "
            << drift * 1e3 << " mm in 5 s" << std::endl;
  EXPECT_GT(moved, 0.03);
  EXPECT_EQ(worst_velocity, 0.0);
  EXPECT_LT(worst_offset, 3e-3);  // 1.04e-3 rad measured in three runs (issue 21: within about 3x)
  EXPECT_LT(drift, 1e-3);
}

TEST(PhysicsOperator, StoppedJointStatesAbortTheGoalAndTheArmHoldsWhereItWas)
{
  const auto q0 = cell->q();
  cell->arm.sendGoal(move("ur5e_", q0, { 0.6, 0, 0, 0, 0, 0 }, 3.0));
  ros::Duration(1.0).sleep();
  std_srvs::Trigger pause;
  call("/physics/pause", pause);
  const ros::WallTime paused = ros::WallTime::now();
  const auto at_pause = cell->q();
  ASSERT_TRUE(cell->arm.waitForResult(ros::Duration(0)));  // sim time stands still: wait in wall time
  const double waited = (ros::WallTime::now() - paused).toSec();
  EXPECT_EQ(cell->arm.getState(), State::ABORTED);
  const std::string why = cell->arm.getResult()->error_string;
  EXPECT_EQ(why.rfind("aborted: no joint_states for ", 0), 0u) << why;
  EXPECT_NE(why.find("(state_timeout 1 s): is the physics node running?"), std::string::npos) << why;

  cell->arm.sendGoal(move("ur5e_", at_pause, { -0.2, 0, 0, 0, 0, 0 }, 1.0));
  ASSERT_TRUE(cell->arm.waitForResult(ros::Duration(0)));
  EXPECT_EQ(cell->arm.getState(), State::REJECTED);
  EXPECT_NE(cell->arm.getResult()->error_string.find("is the physics node running?"), std::string::npos);

  std_srvs::Trigger resume;
  call("/physics/resume", resume);
  ros::Duration(1.5).sleep();
  const auto after = cell->q();
  double moved = 0.0;
  for (size_t j = 0; j < 6; ++j)
    moved = std::max(moved, std::abs(after[j] - at_pause[j]));
  std::cout << "stale states: result " << waited << " s (wall) after the pause; after resuming the arm moved "
            << moved << " rad (the aborted goal would have moved the pan joint " << q0[0] + 0.6 - at_pause[0]
            << " rad more)" << std::endl;
  EXPECT_LT(waited, 5.0);
  // the arm was moving at about 0.27 rad/s when the simulation froze; the rigid drive brakes that
  // momentum within a few ms of simulated time (a few mrad), and nothing moves it on towards the goal
  EXPECT_LT(moved, 0.01);
  ros::Duration(0.5).sleep();
  const auto later = cell->q();
  for (size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(later[j], after[j], 1e-4) << "still moving";
  cell->arm.sendGoal(move("ur5e_", after, { -0.1, 0, 0, 0, 0, 0 }, 1.0));
  ASSERT_TRUE(cell->arm.waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(cell->arm.getState(), State::SUCCEEDED) << cell->arm.getResult()->error_string;
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_physics_operator");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Cell c(nh);
  cell = &c;
  if (!c.arm.waitForServer(ros::Duration(30.0)))
    return 1;
  sensor_msgs::JointState s;
  if (!c.states.waitLatest(s, 10.0))
    return 1;
  ros::Duration(1.0).sleep();  // settle
  return RUN_ALL_TESTS();
}
