#pragma once
#include <actionlib/client/action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <mutex>
#include <string>
#include <vrrw_interaction/ghost_robot.h>

namespace vrrw_interaction
{
/// \brief A robot's arm controller (FollowJointTrajectory) as the ghost's execute uses it: every goal is
/// tracked by its own handle, so a caller hears what became of its goal (a newer goal, ours or anyone's,
/// preempts it; the controller may reject or abort it), never the result of another.
class ArmExecution
{
public:
  /// \brief The action /<robot>/arm_controller/follow_joint_trajectory; its callbacks come on the node's queue.
  explicit ArmExecution(const std::string& robot);

  /// \brief Sends `trajectory` and waits for the goal's end: success only when it SUCCEEDED with error_code 0;
  /// otherwise "execute: PREEMPTED: <error_string>" and the like. Waits at most `duration` + 30 s of ROS time
  /// (simulated time in physics) and gives up at once when the controller goes away. Blocks the calling
  /// thread for the whole motion: call it from an execution thread, never a spinner thread of the node.
  Outcome run(const trajectory_msgs::JointTrajectory& trajectory, double duration,
              control_msgs::FollowJointTrajectoryResult& result);
  /// \brief Sends `trajectory` without waiting (the marker's menu).
  Outcome send(const trajectory_msgs::JointTrajectory& trajectory);

private:
  using Client = actionlib::ActionClient<control_msgs::FollowJointTrajectoryAction>;
  bool ready();

  std::string action_;
  Client client_;  ///< thread-safe by itself
  std::mutex sent_mutex_;
  Client::GoalHandle sent_;  ///< PROTECTED BY sent_mutex_: the menu's last goal (kept so it stays tracked)
};
}  // namespace vrrw_interaction
