#pragma once
#include <ros/ros.h>
#include <trajectory_msgs/JointTrajectory.h>
#include <vrrw_control/ros/arm_action_server.h>
#include <vrrw_control/arm_controller.h>

namespace vrrw_control
{
/// \brief joint_trajectory_controller's streaming interface, `arm_controller/command`
/// (trajectory_msgs/JointTrajectory): every message passes the gate and is spliced in like a goal,
/// without tolerances or a result; it preempts a running action goal. An empty trajectory stops the
/// arm with bounded deceleration. A rejected message logs one line and is published on
/// `arm_controller/errors` (std_msgs/String). Not in real mode: a real arm takes whole goals.
class ArmCommandTopic
{
public:
  /// \brief `options`: the arm server's clock and origin.
  ArmCommandTopic(ros::NodeHandle& nh, ArmController& arm, ArmActionServer& server, const RobotHardware& hardware,
                  const ArmActionServer::Options& options, bool real_mode);

private:
  void onCommand(const trajectory_msgs::JointTrajectory& msg);
  void reject(const std::string& why);
  double toTime(const ros::Time& t) const { return (t - origin_).toSec(); }

  ArmController& arm_;
  ArmActionServer& server_;
  const RobotHardware& hw_;
  std::function<ros::Time()> clock_;
  ros::Time origin_;
  bool real_mode_;
  std::string name_;
  ros::Subscriber command_;
  ros::Publisher errors_;
};
}  // namespace vrrw_control
