#pragma once
#include <actionlib/client/simple_action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <functional>
#include <string>

namespace vrrw_control
{
/// \brief Hands a validated, simulated and confirmed goal to a real robot driver's
/// FollowJointTrajectory action (ur_robot_driver: scaled_pos_joint_traj_controller/follow_joint_trajectory).
/// The relayed goal is the validated message with two documented changes: joint names lose the
/// robot prefix `<name>_` (a real driver knows `shoulder_pan_joint`, not `ur5e_shoulder_pan_joint`),
/// and header.stamp is zeroed so the driver starts on receipt instead of at a time already past.
class RealDriverRelay
{
public:
  using Goal = control_msgs::FollowJointTrajectoryGoal;
  using Result = control_msgs::FollowJointTrajectoryResult;
  using Done = std::function<void(const actionlib::SimpleClientGoalState&, const Result&)>;
  using Feedback = std::function<void(const control_msgs::FollowJointTrajectoryFeedback&)>;

  RealDriverRelay(const std::string& action, const std::string& prefix);

  /// \brief The goal exactly as the driver will receive it.
  Goal driverGoal(const Goal& validated) const;
  /// \brief Sends; false (nothing sent) when the driver's action server is not connected.
  bool send(const Goal& validated, Done done, Feedback feedback);
  void cancel();
  bool connected() const;
  const std::string& action() const { return action_; }
  /// \brief Puts the robot prefix back on names reported by the driver.
  std::string prefixed(const std::string& joint) const;

private:
  std::string action_, prefix_;
  actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction> client_;
};
}  // namespace vrrw_control
