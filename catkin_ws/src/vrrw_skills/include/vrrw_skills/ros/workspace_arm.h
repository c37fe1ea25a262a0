#pragma once
// One arm of the running workspace as a skill run needs it: its joints (joint_states), where frames are (tf),
// its controllers' actions (FollowJointTrajectory, GripperCommand), the mode they run in.
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_listener.h>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_skills/skill.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_skills
{
class WorkspaceArm
{
public:
  /// \brief Robot \a robot of the running scene (its /scene/robots parameters and /robot_description); throws
  /// SkillError naming the robot when the scene has no such robot.
  WorkspaceArm(ros::NodeHandle& node, const std::string& robot, vrrw_common::PersistentServices& services);

  const std::string& robot() const { return robot_; }
  const std::vector<std::string>& armJoints() const { return arm_joints_; }
  const std::string& tcpLink() const { return tcp_link_; }
  /// \brief The arm joints' URDF velocity limits, rad/s.
  const std::vector<double>& maxVelocities() const { return max_velocity_; }
  /// \brief The arm joints' acceleration limits (the scene's robot config), rad/s^2.
  const std::vector<double>& maxAccelerations() const { return max_acceleration_; }
  /// \brief "fake", "physics" or "real": the arm controller's mode.
  const std::string& mode() const { return mode_; }

  /// \brief Waits (simulated time) up to \a seconds for a joint state and the controllers; throws SkillRefusal.
  void waitUntilReady(double seconds);
  /// \brief The latest measured arm joints.
  std::vector<double> joints() const;
  /// \brief The fastest joint's speed in the latest joint state, rad/s.
  double speed() const;
  /// \brief A frame's pose in the world from tf, or nothing.
  std::optional<CartesianPose> pose(const std::string& frame) const;

  /// \brief One FollowJointTrajectory goal, waited for (simulated time); in real mode confirmed once its
  /// simulation ended. Throws SkillRefusal naming \a instruction and the controller's answer.
  void execute(const std::string& instruction, const vrrw_trajectory::JointTrajectory& trajectory);
  /// \brief One GripperCommand goal; a stall on the object succeeds. Throws SkillRefusal.
  void grip(const std::string& instruction, double position, double max_effort);

  /// \brief Set from a signal handler: the goal being waited for is cancelled and the wait ends
  /// (SkillRefusal "interrupted"). Ctrl-C on a tool cancels what it started.
  static void interrupt();

private:
  /// Waits for \a client's goal until done, \a seconds of simulated time or an interrupt (cancels then).
  template <class Client>
  void waitFor(Client& client, const std::string& instruction, const std::string& what, double seconds);
  void onJointStates(const sensor_msgs::JointState::ConstPtr& message);
  void confirmReal(const std::string& instruction, double seconds);

  std::string robot_;
  std::vector<std::string> arm_joints_;
  std::string tcp_link_;
  std::vector<double> max_velocity_;
  std::vector<double> max_acceleration_;
  std::string mode_;
  vrrw_common::PersistentServices& services_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction> arm_;
  actionlib::SimpleActionClient<control_msgs::GripperCommandAction> gripper_;
  ros::Subscriber joint_states_;

  mutable std::mutex mutex_;          ///< protects latest_ and speed_
  std::vector<double> latest_;        ///< PROTECTED BY mutex_
  double speed_ = 0.0;                ///< PROTECTED BY mutex_
};
}  // namespace vrrw_skills
