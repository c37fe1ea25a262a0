#include "arm_execution.h"

#include <condition_variable>
#include <memory>

namespace vrrw_interaction
{
namespace
{
/// What became of one goal: filled by the action client's transition callback, read by the waiting caller.
struct GoalEnd
{
  std::mutex mutex;
  std::condition_variable changed;
  bool done = false;  ///< PROTECTED BY mutex, as the two below
  actionlib::TerminalState state{ actionlib::TerminalState::LOST };
  control_msgs::FollowJointTrajectoryResult result;
};
}  // namespace

ArmExecution::ArmExecution(const std::string& robot)
  : action_("/" + robot + "/arm_controller/follow_joint_trajectory"), client_(action_)
{
}

bool ArmExecution::ready()
{
  return client_.isServerConnected() || client_.waitForActionServerToStart(ros::Duration(2.0));
}

Outcome ArmExecution::run(const trajectory_msgs::JointTrajectory& trajectory, double duration,
                          control_msgs::FollowJointTrajectoryResult& result)
{
  if (!ready())
    return { false, "execute: " + action_ + " is not running" };
  auto end = std::make_shared<GoalEnd>();
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = trajectory;
  Client::GoalHandle handle = client_.sendGoal(goal, [end](Client::GoalHandle gh) {
    if (gh.getCommState() != actionlib::CommState::DONE)
      return;
    std::lock_guard<std::mutex> lock(end->mutex);
    end->state = gh.getTerminalState();
    if (const auto answer = gh.getResult())
      end->result = *answer;
    end->done = true;
    end->changed.notify_all();
  });
  // The motion takes `duration` of ROS time (simulated in physics, which may run slower or faster than the
  // wall clock); the wall-clock wait below only paces the checks for the deadline and the server.
  const ros::Time deadline = ros::Time::now() + ros::Duration(duration + 30.0);
  std::unique_lock<std::mutex> lock(end->mutex);
  while (!end->changed.wait_for(lock, std::chrono::milliseconds(100), [&] { return end->done; }))
  {
    if (!client_.isServerConnected() || !ros::ok())
      return { false, "execute: " + action_ + " went away during the motion" };
    if (ros::Time::now() > deadline)
    {
      lock.unlock();  // cancel() calls the transition callback, which takes the lock
      handle.cancel();
      return { false, "execute: no result within " + std::to_string(duration + 30.0) + " s (cancelled)" };
    }
  }
  result = end->result;
  const bool ok = end->state == actionlib::TerminalState::SUCCEEDED &&
                  result.error_code == control_msgs::FollowJointTrajectoryResult::SUCCESSFUL;
  return { ok, ok ? "executed" : "execute: " + end->state.toString() + ": " + result.error_string };
}

Outcome ArmExecution::send(const trajectory_msgs::JointTrajectory& trajectory)
{
  if (!client_.isServerConnected())
    return { false, "execute: " + action_ + " is not running" };
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = trajectory;
  std::lock_guard<std::mutex> lock(sent_mutex_);
  sent_ = client_.sendGoal(goal);
  return { true, "sent" };
}
}  // namespace vrrw_interaction
