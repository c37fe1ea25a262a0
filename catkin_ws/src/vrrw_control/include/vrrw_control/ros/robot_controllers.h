#pragma once
#include <functional>
#include <memory>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/ros/arm_action_server.h>
#include <vrrw_control/ros/arm_command_topic.h>
#include <vrrw_control/drive_link.h>
#include <vrrw_control/ros/gripper_action_server.h>
#include <vrrw_control/real_robot.h>
#include <vrrw_control/ros/robot_description.h>

namespace vrrw_control
{
/// \brief The controllers of one robot on its hardware, as controller_node (fake, real) and physics_node's
/// plugin (physics) run them: the arm's FollowJointTrajectory action and command topic, the gripper's
/// GripperCommand action and free-drive, in namespace `nh`, parameters from `pnh` (README: Parameters).
/// A control cycle is read, update, write at the time of `clock`.
class RobotControllers
{
public:
  RobotControllers(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name, const RobotDescription& robot,
                   const std::string& mode, std::unique_ptr<RobotHardware> hardware,
                   std::function<ros::Time()> clock);
  ~RobotControllers();

  /// \brief The joints the controllers command: the arm's, then the gripper's actuated joint.
  static std::vector<std::string> joints(const RobotDescription& robot);

  /// \brief One control cycle at `now` (`period` s after the last).
  void cycle(const ros::Time& now, double period);
  /// \brief true while no goal runs (or awaits its confirmation or the real driver).
  bool idle() const;
  /// \brief Ends running goals (`why`); the arm then holds what is measured.
  void interrupt(const std::string& why);
  RobotHardware& hardware() { return *hw_; }

private:
  void makeArm(ros::NodeHandle& pnh);
  std::unique_ptr<RealDriverRelay> makeRealRelay(ros::NodeHandle& pnh);
  void makeGripper(ros::NodeHandle& pnh);

  ros::NodeHandle nh_;
  std::string name_, mode_;
  RobotDescription robot_;
  std::unique_ptr<RobotHardware> hw_;
  std::function<ros::Time()> clock_;
  std::unique_ptr<DriveLink> real_link_;
  std::unique_ptr<RealRobot> real_;
  std::unique_ptr<ArmController> arm_;
  ArmActionServer::Options server_options_;
  std::unique_ptr<ArmActionServer> arm_server_;
  std::unique_ptr<ArmCommandTopic> command_;
  std::unique_ptr<GripperController> gripper_;
  std::unique_ptr<GripperActionServer> gripper_server_;
  ros::Subscriber free_drive_;
};
}  // namespace vrrw_control
