// vrrw_arm: execute a CSV, joint values or a gripper position on a running workspace's controller,
// or plan a motion through /<robot>/plan and execute it; prints progress and the result.
#include <actionlib/client/simple_action_client.h>
#include <charconv>
#include <cmath>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <iostream>
#include <map>
#include <ros/ros.h>
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

struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// `--key value` or `--key=value` after the command and the robot.
std::map<std::string, std::string> options(int argc, char** argv)
{
  std::map<std::string, std::string> found;
  for (int i = 3; i < argc; ++i)
  {
    std::string word = argv[i];
    if (word.rfind("--", 0) != 0)
      throw UsageError("unexpected argument '" + word + "'");
    const auto equals = word.find('=');
    if (equals != std::string::npos)
      found[word.substr(2, equals - 2)] = word.substr(equals + 1);
    else if (i + 1 < argc)
      found[word.substr(2)] = argv[++i];
    else
      throw UsageError(word + " needs a value");
  }
  return found;
}

std::vector<double> numbers(const std::string& text, const std::string& what)
{
  std::vector<double> values;
  for (size_t begin = 0; begin <= text.size();)
  {
    const size_t comma = std::min(text.find(',', begin), text.size());
    double value = 0.0;
    const auto parsed = std::from_chars(text.data() + begin, text.data() + comma, value);
    if (parsed.ec != std::errc() || parsed.ptr != text.data() + comma || !std::isfinite(value))
      throw std::runtime_error(what + ": '" + text.substr(begin, comma - begin) + "' is not a finite number");
    values.push_back(value);
    begin = comma + 1;
  }
  return values;
}

std::vector<std::string> armJoints(const std::string& robot)
{
  std::vector<std::string> joints;
  if (!ros::param::get("/scene/robots/" + robot + "/arm_joints", joints))
    throw std::runtime_error("robot '" + robot + "': no /scene/robots/" + robot +
                             "/arm_joints (is the workspace up with this robot? ./vrrw up SCENE)");
  return joints;
}

trajectory_msgs::JointTrajectory toJoints(const std::string& robot, const std::string& text, double duration)
{
  const auto joints = armJoints(robot);
  const auto q = numbers(text, "--joints");
  if (q.size() != joints.size())
    throw std::runtime_error("--joints: " + std::to_string(q.size()) + " values for the " +
                             std::to_string(joints.size()) + " arm joints of " + robot);
  if (!(duration >= 0.0))
    throw std::runtime_error("--duration: must be >= 0 s");
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

trajectory_msgs::JointTrajectory plan(const std::string& robot, const std::map<std::string, std::string>& o)
{
  vrrw_msgs::Plan srv;
  if (o.count("joints"))
  {
    srv.request.goal_joints.name = armJoints(robot);
    srv.request.goal_joints.position = toJoints(robot, o.at("joints"), 0.0).points[0].positions;
  }
  else if (o.count("pose"))
  {
    const auto p = numbers(o.at("pose"), "--pose");
    if (p.size() != 7)
      throw std::runtime_error("--pose: " + std::to_string(p.size()) + " values, expected x,y,z,qx,qy,qz,qw");
    auto& pose = srv.request.goal_pose;
    pose.header.frame_id = o.count("frame") ? o.at("frame") : "world";
    pose.pose.position.x = p[0], pose.pose.position.y = p[1], pose.pose.position.z = p[2];
    pose.pose.orientation.x = p[3], pose.pose.orientation.y = p[4], pose.pose.orientation.z = p[5];
    pose.pose.orientation.w = p[6];
  }
  else
    throw UsageError("move: give --joints or --pose");
  srv.request.seed = o.count("seed") ? static_cast<uint64_t>(numbers(o.at("seed"), "--seed").at(0)) : 0;
  const std::string service = "/" + robot + "/plan";
  if (!ros::service::waitForService(service, ros::Duration(5.0)))
    throw std::runtime_error(service + ": no planning service (is the workspace up? ./vrrw up SCENE)");
  if (!ros::service::call(service, srv))
    throw std::runtime_error(service + ": the call failed");
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
  if (argc < 3)
    throw UsageError(command + ": no robot");
  const std::string robot = argv[2];
  const auto o = options(argc, argv);
  if (!ros::master::check())
    throw std::runtime_error("no ROS master at " + ros::master::getURI() + " (start the workspace: ./vrrw up SCENE)");
  if (command == "move")
    return execute(robot, plan(robot, o));
  if (o.count("csv"))
    return execute(robot, fromCsv(robot, o.at("csv")));
  if (o.count("joints"))
    return execute(robot, toJoints(robot, o.at("joints"), o.count("duration") ? numbers(o.at("duration"), "--duration").at(0) : 0.0));
  if (o.count("gripper"))
    return gripper(robot, numbers(o.at("gripper"), "--gripper").at(0),
                   o.count("effort") ? numbers(o.at("effort"), "--effort").at(0) : 0.0);
  throw UsageError("send: give --csv, --joints or --gripper");
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "vrrw_arm", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  try
  {
    return run(argc, argv);
  }
  catch (const UsageError& e)
  {
    std::cerr << "vrrw_arm: " << e.what() << "\n" << kUsage;
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_arm: " << e.what() << "\n";
    return 1;
  }
}
