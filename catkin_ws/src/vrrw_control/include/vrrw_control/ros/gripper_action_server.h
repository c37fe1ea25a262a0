#pragma once
#include <control_msgs/GripperCommandAction.h>
#include <ros/ros.h>
#include <vrrw_control/ros/arm_action_server.h>
#include <vrrw_control/gripper_controller.h>

namespace vrrw_control
{
/// \brief The GripperCommand action of one gripper: position of the actuated joint, feedback every
/// cycle, result reached_goal or stalled (succeeded when stalling is allowed, aborted otherwise);
/// `max_effort` (pad force, N) bounds the squeeze through the actuated joint's drive force limit.
class GripperActionServer
{
public:
  using Action = control_msgs::GripperCommandAction;
  using GoalHandle = actionlib::ServerGoalHandle<Action>;

  /// \brief `options`: the arm server's clock, origin, queue size and feedback period.
  GripperActionServer(ros::NodeHandle& nh, GripperController& gripper, const RobotHardware& hardware,
                      const ArmActionServer::Options& options, bool allow_stalling);
  void update(const ros::Time& now);
  /// \brief true while a goal runs.
  bool active() const { return has_active_; }
  /// \brief The hardware lost its state (`why`): aborts a running goal.
  void suspend(const std::string& why);

private:
  double toTime(const ros::Time& t) const { return (t - origin_).toSec(); }
  void onGoal(GoalHandle gh);
  void onCancel(GoalHandle gh);

  GripperController& gripper_;
  const RobotHardware& hw_;
  std::function<ros::Time()> clock_;
  ros::Time origin_;
  double feedback_period_;
  ros::Time last_feedback_;  ///< of the active goal
  bool allow_stalling_;
  ClockedActionServer<Action> server_;
  GoalHandle active_;
  bool has_active_ = false;
};
}  // namespace vrrw_control
