// vrrw_arm: execute a CSV, joint values or a gripper position on a running workspace's controller,
// or plan a motion through /<robot>/plan and execute it; prints progress and the result.
#include <actionlib/client/simple_action_client.h>
#include <cmath>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <iostream>
#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_msgs/Plan.h>
#include <vrrw_trajectory/csv.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace
{
const char* const kUsage =
    "usage: vrrw_arm send ROBOT --csv FILE | --joints q1,..,qn [--duration S] | --gripper POS [--effort N]\n"
    "       vrrw_arm move ROBOT --joints q1,..,qn | --pose x,y,z,qx,qy,qz,qw [--frame F] [--seed N]\n"
    "Joint values are the robot's arm joints in /scene/robots/ROBOT/arm_joints order (rad). --duration 0\n"
    "(default) lets the controller choose the fastest motion within the limits (fake and physics mode).\n";

using vrrw_common::Options;

struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

std::vector<std::string> armJoints(const std::string& robot)
{
  std::vector<std::string> joints;
  if (!ros::param::get("/scene/robots/" + robot + "/arm_joints", joints))
    throw std::runtime_error("robot '" + robot + "': no /scene/robots/" + robot +
                             "/arm_joints (is the workspace up with this robot? ./vrrw up SCENE)");
  return joints;
}

trajectory_msgs::JointTrajectory toJoints(const std::string& robot, const Options& o, double duration)
{
  const auto joints = armJoints(robot);
  const auto q = o.list("joints", joints.size());
  trajectory_msgs::JointTrajectory t;
  t.joint_names = joints;
  t.points.resize(1);
  t.points[0].positions = q;
  t.points[0].time_from_start = ros::Duration(duration);
  return t;
}

/// A CSV of the arm (named columns, or the seed's q1..qn in arm joint order), times from 0.
trajectory_msgs::JointTrajectory fromCsv(const std::string& robot, const std::string& path)
{
  auto csv = vrrw_trajectory::readCsv(path);
  const auto joints = armJoints(robot);
  if (csv.joint_names.size() == joints.size() && csv.joint_names.front() == "q1")
    csv.joint_names = joints;
  const double t0 = csv.points.front().time;
  for (auto& p : csv.points)
    p.time -= t0;
  return vrrw_trajectory::toMsg(csv);
}

template <class Client>
void connect(Client& client, const std::string& action)
{
  if (!client.waitForServer(ros::Duration(5.0)))
    throw std::runtime_error(action + ": no controller answers (is the workspace up? ./vrrw up SCENE)");
}

int execute(const std::string& robot, const trajectory_msgs::JointTrajectory& trajectory)
{
  const std::string action = "/" + robot + "/arm_controller/follow_joint_trajectory";
  actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction> client(action, true);
  connect(client, action);
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = trajectory;
  const double duration = trajectory.points.back().time_from_start.toSec();
  std::cout << "sending " << trajectory.points.size() << " points over " << duration << " s to " << action << std::endl;
  ros::WallTime next_line;
  client.sendGoal(goal, {}, {}, [&](const control_msgs::FollowJointTrajectoryFeedbackConstPtr& f) {
    if (ros::WallTime::now() < next_line)
      return;
    next_line = ros::WallTime::now() + ros::WallDuration(0.25);
    double error = 0.0;
    for (double e : f->error.positions)
      error = std::max(error, std::abs(e));
    std::cout << "  t " << f->desired.time_from_start.toSec() << " s, max |error| " << error << " rad" << std::endl;
  });
  client.waitForResult();
  const auto result = client.getResult();
  std::cout << "result: " << client.getState().toString() << " (error_code " << result->error_code << ")"
            << (result->error_string.empty() ? "" : ": " + result->error_string) << std::endl;
  return client.getState() == actionlib::SimpleClientGoalState::SUCCEEDED ? 0 : 1;
}

int gripper(const std::string& robot, double position, double effort)
{
  const std::string action = "/" + robot + "/gripper_controller/gripper_cmd";
  actionlib::SimpleActionClient<control_msgs::GripperCommandAction> client(action, true);
  connect(client, action);
  control_msgs::GripperCommandGoal goal;
  goal.command.position = position;
  goal.command.max_effort = effort;
  client.sendGoal(goal);
  client.waitForResult();
  const auto r = client.getResult();
  std::cout << "result: " << client.getState().toString() << " at " << r->position << (r->stalled ? ", stalled" : "")
            << (r->reached_goal ? ", reached the goal" : "") << std::endl;
  return client.getState() == actionlib::SimpleClientGoalState::SUCCEEDED ? 0 : 1;
}

trajectory_msgs::JointTrajectory plan(const std::string& robot, const Options& o)
{
  vrrw_msgs::Plan srv;
  if (o.oneOf({ "joints", "pose" }) == "joints")
  {
    srv.request.goal_joints.name = armJoints(robot);
    srv.request.goal_joints.position = toJoints(robot, o, 0.0).points[0].positions;
  }
  else
  {
    const auto p = o.list("pose", 7);
    auto& pose = srv.request.goal_pose;
    pose.header.frame_id = o.text("frame", "world");
    pose.pose.position.x = p[0], pose.pose.position.y = p[1], pose.pose.position.z = p[2];
    pose.pose.orientation.x = p[3], pose.pose.orientation.y = p[4], pose.pose.orientation.z = p[5];
    pose.pose.orientation.w = p[6];
  }
  srv.request.seed = o.count("seed", 0, 0, UINT64_MAX);
  const std::string service = "/" + robot + "/plan";
  vrrw_common::services().call(service, srv);
  if (srv.response.error_code != 0)
    throw std::runtime_error(service + ": " + srv.response.message);
  std::cout << "planned in " << srv.response.planning_time << " s: " << srv.response.trajectory.points.size()
            << " points, path length " << srv.response.path_length << " rad" << std::endl;
  return srv.response.trajectory;
}

int run(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command != "send" && command != "move")
    throw UsageError(command.empty() ? "no command" : "unknown command '" + command + "'");
  if (argc < 3 || std::string(argv[2]).rfind("--", 0) == 0)
    throw UsageError(command + ": no robot");
  const std::string robot = argv[2];
  const Options o(argc, argv, 3, { "csv", "joints", "duration", "gripper", "effort", "pose", "frame", "seed" });
  o.expectPositional({});
  const std::string what = command == "move" ? o.oneOf({ "joints", "pose" }) : o.oneOf({ "csv", "joints", "gripper" });
  const std::string action = "/" + robot + (what == "gripper" ? "/gripper_controller/gripper_cmd" : "/arm_controller/follow_joint_trajectory");
  vrrw_common::checkWorkspace({ robot, { action }, command == "move" ? std::vector<std::string>{ "/" + robot + "/plan" } : std::vector<std::string>{} });
  ros::AsyncSpinner spinner(1);  // after the check: its NodeHandle would wait for a master forever
  spinner.start();
  if (command == "move")
    return execute(robot, plan(robot, o));
  if (what == "csv")
    return execute(robot, fromCsv(robot, o.text("csv")));
  if (what == "joints")
    return execute(robot, toJoints(robot, o, o.number("duration", 0.0, vrrw_common::Range::closed(0.0, 86400.0, "s"))));
  return gripper(robot, o.number("gripper"), o.number("effort", 0.0));
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "vrrw_arm", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  try
  {
    return run(argc, argv);
  }
  catch (const UsageError& e)
  {
    std::cerr << "vrrw_arm: " << e.what() << "\n" << kUsage;
    return 2;
  }
  catch (const vrrw_common::OptionError& e)
  {
    std::cerr << "vrrw_arm: " << e.what() << "\n";
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_arm: " << e.what() << "\n";
    return 1;
  }
}
