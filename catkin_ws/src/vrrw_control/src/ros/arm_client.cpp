#include "vrrw_control/ros/arm_client.h"

#include <vrrw_common/ros/action_client.h>
#include <cmath>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <cstdio>
#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/topic_graph.h>

namespace vrrw_control
{
std::atomic<bool> ArmClient::stop_requested_{ false };

namespace
{
/// control_msgs' names of FollowJointTrajectory's error codes (0 is success; MoveIt's own codes use 1).
std::string codeName(int code)
{
  using R = control_msgs::FollowJointTrajectoryResult;
  switch (code)
  {
    case R::SUCCESSFUL: return "SUCCESSFUL";
    case R::INVALID_GOAL: return "INVALID_GOAL";
    case R::INVALID_JOINTS: return "INVALID_JOINTS";
    case R::OLD_HEADER_TIMESTAMP: return "OLD_HEADER_TIMESTAMP";
    case R::PATH_TOLERANCE_VIOLATED: return "PATH_TOLERANCE_VIOLATED";
    case R::GOAL_TOLERANCE_VIOLATED: return "GOAL_TOLERANCE_VIOLATED";
    default: return "unknown";
  }
}

std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// Waits (wall clock: the workspace's clock may be paused) until \a client's server is connected, then (at most
/// 1 s) until every other subscriber of the goal topic is: a recorder that connects after the goal misses it.
template <class Client>
void connect(Client& client, const std::string& action, double seconds, std::ostream& out)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); !client.isServerConnected();
       ros::WallDuration(0.02).sleep())
    if (ros::WallTime::now() > end || !ros::ok())
      throw ArmClientError(action + ": no controller answers after " + number(seconds) +
                           " s (is the workspace up with this robot? ./vrrw up SCENE)");
  if (!vrrw_common::waitForSubscribers(action + "/goal", 1.0))
    out << "note: a subscriber of " << action << "/goal did not connect within 1 s: it will not see this goal"
        << std::endl;
}
}  // namespace

ArmClient::ArmClient(const std::string& robot, std::ostream& out, ArmClientLimits limits)
  : robot_(robot), out_(out), limits_(limits)
{
  if (!ros::param::get("/scene/robots/" + robot + "/arm_joints", arm_joints_))
    throw ArmClientError("robot '" + robot + "': no /scene/robots/" + robot + "/arm_joints in the running workspace");
}

trajectory_msgs::JointTrajectory ArmClient::plan(const vrrw_msgs::Plan::Request& request)
{
  const std::string service = "/" + robot_ + "/plan";
  vrrw_msgs::Plan srv;
  srv.request = request;
  try
  {
    // the planner's own time limit, and time for the time parameterization after it
    vrrw_common::services().call(service, srv, std::max(0.0, request.time_limit) + 60.0);
  }
  catch (const vrrw_common::ServiceError& e)
  {
    throw ArmClientError(e.what());
  }
  if (srv.response.error_code != 0)
    throw ArmClientError(service + ": " + srv.response.message + " (error_code " +
                         std::to_string(srv.response.error_code) + ")");
  out_ << "planned in " << number(srv.response.planning_time) << " s: " << trajectorySummary(srv.response.trajectory)
       << ", path length " << number(srv.response.path_length) << " rad" << std::endl;
  return srv.response.trajectory;
}

GoalOutcome ArmClient::follow(const trajectory_msgs::JointTrajectory& trajectory)
{
  const std::string action = "/" + robot_ + "/arm_controller/follow_joint_trajectory";
  vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction> client(action);
  connect(client, action, limits_.server_wait, out_);
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = trajectory;
  const double duration = trajectory.points.empty() ? 0.0 : trajectory.points.back().time_from_start.toSec();
  out_ << "sending " << trajectory.points.size() << " points over " << duration << " s to " << action << std::endl;
  ros::WallTime next_line;
  client.sendGoal(goal, {}, {}, [&](const control_msgs::FollowJointTrajectoryFeedbackConstPtr& f) {
    if (ros::WallTime::now() < next_line)
      return;
    next_line = ros::WallTime::now() + ros::WallDuration(0.25);
    double error = 0.0;
    for (double e : f->error.positions)
      error = std::max(error, std::abs(e));
    out_ << "  t " << f->desired.time_from_start.toSec() << " s, max |error| " << error << " rad" << std::endl;
  });
  GoalOutcome outcome = waitFor(client, action, duration);
  const auto result = client.getResult();
  const int code = result ? result->error_code : 0;
  if (result && !result->error_string.empty())
    outcome.text = result->error_string;
  out_ << "result: " << outcome.state << " (error_code " << code << " " << codeName(code) << ")"
       << (outcome.text.empty() ? "" : ": " + outcome.text) << std::endl;
  return outcome;
}

GoalOutcome ArmClient::grip(double position, double effort)
{
  const std::string action = "/" + robot_ + "/gripper_controller/gripper_cmd";
  vrrw_common::ActionClient<control_msgs::GripperCommandAction> client(action);
  connect(client, action, limits_.server_wait, out_);
  control_msgs::GripperCommandGoal goal;
  goal.command.position = position;
  goal.command.max_effort = effort;
  client.sendGoal(goal);
  GoalOutcome outcome = waitFor(client, action, 0.0);
  const auto r = client.getResult();
  out_ << "result: " << outcome.state;
  if (outcome.state == "REJECTED")
    out_ << ": " << (outcome.text.empty() ? "refused by the controller" : outcome.text);
  else if (r)
    out_ << " at " << r->position << (r->stalled ? ", stalled" : "") << (r->reached_goal ? ", reached the goal" : "")
         << (outcome.text.empty() ? "" : " (" + outcome.text + ")");
  out_ << std::endl;
  return outcome;
}

/// Polls \a client until its goal is done: cancels it on requestStop(), gives up on a server gone for
/// gone_after s or on no result result_slack s (ROS time) after the trajectory's \a expected_seconds.
template <class Client>
GoalOutcome ArmClient::waitFor(Client& client, const std::string& action, double expected_seconds)
{
  GoalOutcome outcome;
  const ros::Time deadline = ros::Time::now() + ros::Duration(expected_seconds + limits_.result_slack);
  ros::WallTime last_seen = ros::WallTime::now();
  while (!client.getState().isDone())
  {
    const ros::WallTime now = ros::WallTime::now();
    if (stop_requested_)
    {
      out_ << "interrupted: cancelling the goal" << std::endl;
      client.cancelGoal();
      for (const ros::WallTime end = now + ros::WallDuration(limits_.cancel_wait);
           !client.getState().isDone() && ros::WallTime::now() < end;)
        ros::WallDuration(0.02).sleep();
      outcome.interrupted = true;
      break;
    }
    if (client.isServerConnected())
      last_seen = now;
    else if ((now - last_seen).toSec() > limits_.gone_after)
      throw ArmClientError(action + ": the controller went away during the goal (no status for " +
                           number(limits_.gone_after) + " s); where the arm stopped is unknown");
    if (ros::Time::now() > deadline)
    {
      client.cancelGoal();
      throw ArmClientError(action + ": no result " + number(limits_.result_slack) +
                           " s after the motion's end; the goal was cancelled");
    }
    ros::WallDuration(0.02).sleep();
  }
  const auto state = client.getState();
  outcome.state = state.toString();
  outcome.text = state.getText();
  return outcome;
}

vrrw_msgs::Plan::Request planRequest(const vrrw_common::Options& options, const std::vector<std::string>& arm_joints)
{
  vrrw_msgs::Plan::Request request;
  if (options.has("joints"))
  {
    request.goal_joints.name = arm_joints;
    request.goal_joints.position = options.list("joints", arm_joints.size());
  }
  else if (options.has("pose"))
  {
    const auto p = options.list("pose", 7);
    auto& pose = request.goal_pose;
    pose.header.frame_id = options.text("frame", "world");
    pose.pose.position.x = p[0], pose.pose.position.y = p[1], pose.pose.position.z = p[2];
    pose.pose.orientation.x = p[3], pose.pose.orientation.y = p[4], pose.pose.orientation.z = p[5];
    pose.pose.orientation.w = p[6];
  }
  else
    throw vrrw_common::OptionError("give one of --joints, --pose");
  request.seed = options.count("seed", 0, 0, UINT64_MAX);
  return request;
}

std::string trajectorySummary(const trajectory_msgs::JointTrajectory& trajectory)
{
  double top = 0.0;
  std::string joint;
  const auto& points = trajectory.points;
  for (std::size_t k = 0; k < points.size(); ++k)
    for (std::size_t j = 0; j < trajectory.joint_names.size() && j < points[k].positions.size(); ++j)
    {
      // the stated velocity; between points without one, the difference quotient
      double speed = j < points[k].velocities.size() ? std::abs(points[k].velocities[j]) : 0.0;
      if (points[k].velocities.empty() && k > 0)
      {
        const double dt = (points[k].time_from_start - points[k - 1].time_from_start).toSec();
        speed = dt > 0 ? std::abs(points[k].positions[j] - points[k - 1].positions[j]) / dt : 0.0;
      }
      if (speed > top)
        top = speed, joint = trajectory.joint_names[j];
    }
  const double duration = points.empty() ? 0.0 : points.back().time_from_start.toSec();
  return std::to_string(points.size()) + " points over " + number(duration) + " s, max joint speed " + number(top) +
         " rad/s" + (joint.empty() ? "" : " (" + joint + ")");
}
}  // namespace vrrw_control
