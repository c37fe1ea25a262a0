// vrrw_arm: ./vrrw send and ./vrrw move on a running workspace's controllers (vrrw_control::ArmClient).
// Exit codes: 0 done, 1 failed while running, 2 bad input, 130 interrupted (the goal was cancelled).
#include <csignal>
#include <iostream>
#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_control/ros/arm_client.h>
#include <vrrw_trajectory/csv.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace
{
using vrrw_common::Options;
using vrrw_common::OptionError;

const char* const kUsage =
    "usage: vrrw_arm send ROBOT --csv FILE | --joints q1,..,qn [--duration S] | --gripper POS [--effort N]\n"
    "       vrrw_arm move ROBOT --joints q1,..,qn | --pose x,y,z,qx,qy,qz,qw [--frame F] [--seed N]\n"
    "Joint values are the robot's arm joints in /scene/robots/ROBOT/arm_joints order (rad). --duration 0\n"
    "(default) lets the controller choose the fastest motion within the limits (fake and physics mode).\n"
    "Ctrl-C cancels the goal.\n";

/// A command line without a command or robot: the line and the usage.
struct UsageError : OptionError
{
  using OptionError::OptionError;
};

void onSignal(int)
{
  vrrw_control::ArmClient::requestStop();
}

/// Joint values as a one-point goal (time 0: the fastest motion the controller allows).
trajectory_msgs::JointTrajectory toJoints(const std::vector<std::string>& joints, const std::vector<double>& q,
                                          double duration)
{
  trajectory_msgs::JointTrajectory t;
  t.joint_names = joints;
  t.points.resize(1);
  t.points[0].positions = q;
  t.points[0].time_from_start = ros::Duration(duration);
  return t;
}

/// A CSV of the arm (named columns, or the seed's q1..qn in arm joint order), times from 0.
trajectory_msgs::JointTrajectory fromCsv(const std::string& path, const std::vector<std::string>& joints)
{
  auto csv = vrrw_trajectory::readCsv(path);
  if (csv.joint_names.size() == joints.size() && csv.joint_names.front() == "q1")
    csv.joint_names = joints;
  const double t0 = csv.points.front().time;
  for (auto& p : csv.points)
    p.time -= t0;
  return vrrw_trajectory::toMsg(csv);
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
  // Every option is checked before the workspace is touched; the joint count needs the robot's joints.
  const std::string what = command == "move" ? o.oneOf({ "joints", "pose" }) : o.oneOf({ "csv", "joints", "gripper" });
  const double duration = o.number("duration", 0.0, vrrw_common::Range::closed(0.0, 86400.0, "s"));
  const double position = what == "gripper" ? o.number("gripper") : 0.0;
  const double effort = o.number("effort", 0.0);
  o.count("seed", 0, 0, UINT64_MAX);
  const std::string ns = "/" + robot;
  vrrw_common::checkWorkspace(
      { robot,
        { ns + (what == "gripper" ? "/gripper_controller/gripper_cmd" : "/arm_controller/follow_joint_trajectory") },
        command == "move" ? std::vector<std::string>{ ns + "/plan" } : std::vector<std::string>{} });
  ros::AsyncSpinner spinner(1);  // after the check: its NodeHandle would wait for a master forever
  spinner.start();
  vrrw_control::ArmClient arm(robot, std::cout);
  vrrw_control::GoalOutcome outcome;
  if (command == "move")
    outcome = arm.follow(arm.plan(vrrw_control::planRequest(o, arm.armJoints())));
  else if (what == "csv")
    outcome = arm.follow(fromCsv(o.text("csv"), arm.armJoints()));
  else if (what == "joints")
    outcome = arm.follow(toJoints(arm.armJoints(), o.list("joints", arm.armJoints().size()), duration));
  else
    outcome = arm.grip(position, effort);
  return outcome.interrupted ? 130 : outcome.exitCode();
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "vrrw_arm", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const vrrw_common::ToolNode node_registration;
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  try
  {
    return run(argc, argv);
  }
  catch (const UsageError& e)
  {
    std::cerr << "vrrw_arm: " << e.what() << "\n" << kUsage;
    return 2;
  }
  catch (const OptionError& e)
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
