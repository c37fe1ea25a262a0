#include <vrrw_control/ros/gripper_action_server.h>

namespace vrrw_control
{
GripperActionServer::GripperActionServer(ros::NodeHandle& nh, GripperController& gripper,
                                         const RobotHardware& hardware, const ArmActionServer::Options& options,
                                         bool allow_stalling)
  : gripper_(gripper)
  , hw_(hardware)
  , clock_(options.clock)
  , origin_(options.clock_origin)
  , feedback_period_(options.feedback_period)
  , allow_stalling_(allow_stalling)
  , server_(actionParameters(nh, "gripper_controller/gripper_cmd", options), "gripper_controller/gripper_cmd",
            options.status_period, [this](GoalHandle gh) { onGoal(gh); }, [this](GoalHandle gh) { onCancel(gh); })
{
  server_.start();
}

void GripperActionServer::onGoal(GoalHandle gh)
{
  const auto goal = gh.getGoal();
  const std::string bad = hw_.ready() ? gripper_.check(goal->command.position, goal->command.max_effort) : hw_.fault();
  if (!bad.empty())
  {
    gh.setRejected(control_msgs::GripperCommandResult(), bad);
    ROS_WARN_STREAM(ros::this_node::getNamespace() << "/gripper_controller: goal rejected: " << bad);
    return;
  }
  // one goal at a time, as ros_control's gripper_action_controller: the newest wins and moves on from where the
  // fingers are commanded now
  if (has_active_)
    active_.setCanceled(control_msgs::GripperCommandResult(), "preempted by a newer goal");
  gh.setAccepted();
  gripper_.start(goal->command.position, toTime(clock_()), goal->command.max_effort);
  active_ = gh;
  has_active_ = true;
  last_feedback_ = ros::Time();
}

void GripperActionServer::onCancel(GoalHandle gh)
{
  if (!has_active_ || !(gh == active_))
    return;
  gripper_.stop(toTime(clock_()));
  active_.setCanceled(control_msgs::GripperCommandResult(), "canceled");
  has_active_ = false;
}

void GripperActionServer::suspend(const std::string& why)
{
  gripper_.release();
  if (!has_active_)
    return;
  active_.setAborted(control_msgs::GripperCommandResult(), "aborted: " + why);
  has_active_ = false;
}

void GripperActionServer::update(const ros::Time& now)
{
  const auto c = gripper_.update(toTime(now));
  server_.heartbeat(now);
  if (!has_active_)
    return;
  // feedback at the period asked for (1 ns of slack for the clock's rounding), and always with the last cycle
  if (c.done || last_feedback_.isZero() || (now - last_feedback_).toSec() >= feedback_period_ - 1e-9)
  {
    control_msgs::GripperCommandFeedback f;
    f.position = c.position;
    f.effort = c.effort;
    f.stalled = c.stalled;
    f.reached_goal = c.reached_goal;
    active_.publishFeedback(f);
    last_feedback_ = now;
  }
  if (!c.done)
    return;
  control_msgs::GripperCommandResult r;
  r.position = c.position;
  r.effort = c.effort;
  r.stalled = c.stalled;
  r.reached_goal = c.reached_goal;
  // A stall is how a grasp ends (the fingers closed on an object), so it succeeds unless stalling is not allowed
  if (c.reached_goal || (c.stalled && allow_stalling_))
    active_.setSucceeded(r, c.stalled ? "stalled (fingers closed on an object)" : "");
  else
    active_.setAborted(r, c.stalled ? "stalled short of the goal" : "goal not reached in time");
  has_active_ = false;
}
}  // namespace vrrw_control
