#pragma once
#include <actionlib/server/action_server.h>
#include <control_msgs/GripperCommandAction.h>
#include <ros/ros.h>
#include <vrrw_control/gripper_controller.h>

namespace vrrw_control
{
/// \brief The GripperCommand action of one gripper: position of the actuated joint, feedback every
/// cycle, result reached_goal or stalled (succeeded when stalling is allowed, aborted otherwise).
class GripperActionServer
{
public:
  using Action = control_msgs::GripperCommandAction;
  using GoalHandle = actionlib::ServerGoalHandle<Action>;

  GripperActionServer(ros::NodeHandle& nh, GripperController& gripper, const ros::Time& clock_origin,
                      bool allow_stalling);
  void update(const ros::Time& now);

private:
  double toTime(const ros::Time& t) const { return (t - origin_).toSec(); }
  void onGoal(GoalHandle gh);
  void onCancel(GoalHandle gh);

  GripperController& gripper_;
  ros::Time origin_;
  bool allow_stalling_;
  actionlib::ActionServer<Action> server_;
  GoalHandle active_;
  bool has_active_ = false;
};
}  // namespace vrrw_control
