// demo_relay: stage 5 of `./vrrw demo --real NS`: the demonstration's instructions through the controller's
// real relay, on the robot's master.
//   demo_relay --scene S --bag BAG --out relay.json [--yes]
// Beside the real driver runs a vrrw controller in real mode for the scene's robot (run_demo.py starts it).
// Each arm instruction is the goal stage 3 replayed (the recorded samples between the bag's annotations): the
// controller runs it in simulation, holds it until the confirmation sent here, then hands it to the driver.
// Gripper goals run in simulation only (a real gripper has its own driver). Without --yes the operator types yes.
#include <actionlib/client/simple_action_client.h>
#include <algorithm>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <fstream>
#include <iostream>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_srvs/Trigger.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_evaluation/demo_cell.h>
#include <vrrw_evaluation/demo_report.h>
#include <vrrw_evaluation/pick_place_task.h>
#include <vrrw_kinematics/robot_model.h>
#include <vrrw_trajectory/msg_conversions.h>

#include <vrrw_demos/ros/demo_bag.h>
#include <vrrw_evaluation/annotations.h>
#include <vrrw_evaluation/joint_paths.h>

using namespace vrrw_evaluation;

namespace
{
using ArmClient = actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>;
using GripperClient = actionlib::SimpleActionClient<control_msgs::GripperCommandAction>;

struct Relayed
{
  std::string name, kind, state, message;
  std::size_t points = 0;
  double seconds = 0.0;
};

void progress(const std::string& line)
{
  std::cout << "demo: relay: " << line << std::endl;
}

void progress(const Relayed& r)
{
  progress(r.name + ": " + r.state + " (" + r.kind + ") " + r.message);
}

class Relay
{
public:
  explicit Relay(const std::string& robot)
    : ns_("/" + robot + "/")
    , arm_(ns_ + "arm_controller/follow_joint_trajectory", true)
    , gripper_(ns_ + "gripper_controller/gripper_cmd", true)
  {
  }

  /// The controller in real mode with its actions and confirmation; one line naming what is missing.
  bool ready(std::string& driver, std::string& error)
  {
    ros::NodeHandle nh;
    std::string mode;  // roslaunch sets it as the controller starts
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(15.0);
         !nh.getParam(ns_ + "controller/mode", mode) && ros::WallTime::now() < end;)
      ros::WallDuration(0.1).sleep();
    if (mode != "real")
      return error = ns_ + "controller/mode is '" + mode + "', not real: no real relay runs", false;
    driver = nh.param<std::string>(ns_ + "controller/real_driver_action", "");
    if (!arm_.waitForServer(ros::Duration(15.0)) || !gripper_.waitForServer(ros::Duration(5.0)))
      return error = ns_ + "arm_controller / gripper_controller do not answer", false;
    if (!ros::service::waitForService(ns_ + "arm_controller/confirm_real_execution", ros::Duration(5.0)))
      return error = "no " + ns_ + "arm_controller/confirm_real_execution", false;
    return true;
  }

  /// The arm as the controller measures it (the real arm's state when the driver publishes it).
  std::optional<std::vector<double>> measured(const std::vector<std::string>& joints)
  {
    const auto state = ros::topic::waitForMessage<sensor_msgs::JointState>(ns_ + "joint_states", ros::Duration(5.0));
    if (!state)
      return std::nullopt;
    return vrrw_common::findValues(state->name, state->position, joints);
  }

  /// Waits until the measured arm is within `tolerance` of `q` (the controller's gate checks the start of a
  /// goal against it: the driver's joint_states may trail its result).
  void waitUntilAt(const std::vector<std::string>& joints, const std::vector<double>& q, double tolerance, double seconds)
  {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;)
    {
      const auto now = measured(joints);
      if (now && largestJointDifference(*now, q) < tolerance)
        return;
    }
  }

  Relayed arm(const std::string& name, const vrrw_trajectory::JointTrajectory& motion)
  {
    Relayed r{ name, "arm", "", "", motion.points.size(), motion.duration() };
    control_msgs::FollowJointTrajectoryGoal goal;
    goal.trajectory = vrrw_trajectory::toMsg(motion);
    arm_.sendGoal(goal);
    // the controller runs it in simulation first ("still running in simulation"), then holds it for this
    if (!confirmAfterSimulation(motion.duration() + 10.0))
      r.message = "not confirmed: " + confirm_message_ + "; ";
    if (!arm_.waitForResult(ros::Duration(motion.duration() + 60.0)))
    {
      arm_.cancelGoal();
      return r.state = "TIMEOUT", r.message += "no result; cancelled", r;
    }
    r.state = arm_.getState().toString();
    r.message += arm_.getResult()->error_string;
    return r;
  }

  Relayed gripper(const std::string& name, double position, double effort)
  {
    Relayed r{ name, "gripper (simulated only)", "", "", 1, 0.0 };
    control_msgs::GripperCommandGoal goal;
    goal.command.position = position;
    goal.command.max_effort = effort;
    gripper_.sendGoal(goal);
    if (!gripper_.waitForResult(ros::Duration(10.0)))
      return gripper_.cancelGoal(), r.state = "TIMEOUT", r;
    r.state = gripper_.getState().toString();
    r.message = gripper_.getState().getText();
    return r;
  }

private:
  /// Confirms the goal once its simulation ended; false when `seconds` passed or the goal ended first.
  bool confirmAfterSimulation(double seconds)
  {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
         ros::WallDuration(0.05).sleep())
    {
      std_srvs::Trigger confirm;
      if (!links_.tryCall(ns_ + "arm_controller/confirm_real_execution", confirm))
        confirm.response.message = "confirm_real_execution did not answer";
      if (confirm.response.success)
        return true;
      confirm_message_ = confirm.response.message;
      if (arm_.getState().isDone())
        return false;
    }
    return false;
  }

  std::string ns_, confirm_message_;
  ArmClient arm_;
  GripperClient gripper_;
  vrrw_common::PersistentServices links_;
};

/// From `from` to `to` at a fifth of the velocity limits, at rest at both ends (as vrrw_demos' replay starts).
vrrw_trajectory::JointTrajectory approach(const std::vector<std::string>& joints, const std::vector<double>& from,
                                          const std::vector<double>& to, const std::vector<double>& max_velocity)
{
  double seconds = 0.5;
  for (std::size_t j = 0; j < joints.size(); ++j)
    seconds = std::max(seconds, 5.0 * std::abs(to[j] - from[j]) / max_velocity[j]);
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = joints;
  trajectory.points = { { 0.0, from, std::vector<double>(joints.size(), 0.0), {} },
                        { seconds, to, std::vector<double>(joints.size(), 0.0), {} } };
  return trajectory;
}

int run(const std::string& scene, const std::string& bag, const std::string& out, bool yes)
{
  Cell cell;
  std::string error;
  if (!findCell(scene, cell, error))
    return std::cerr << "demo: relay: " << error << "\n", 2;
  const std::vector<std::string>& joints = cell.robot.arm_joints;
  std::vector<Segment> instructions;
  vrrw_demos::RobotTrack track;
  try
  {
    const vrrw_demos::Demonstration shown = vrrw_demos::readDemonstration(bag, { cell.robot.name });
    instructions = annotatedInstructions(shown);
    track = shown.robots.front();
  }
  catch (const std::exception& e)
  {
    return std::cerr << "demo: relay: " << e.what() << "\n", 1;
  }
  if (instructions.size() != kInstructions.size() || track.gripper_goals.size() < 2 || track.joint_names != joints)
    return std::cerr << "demo: relay: " << bag << ": not the six instructions and two gripper goals of a demonstration"
                     << " of " << cell.robot.name << "\n", 1;

  ros::NodeHandle node;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Relay relay(cell.robot.name);
  std::string driver;
  if (!relay.ready(driver, error))
    return std::cerr << "demo: relay: " << error << "\n", 1;
  if (!yes)
  {
    std::cout << "demo: relay: the demonstration's " << kInstructions.size() << " instructions will move the REAL robot "
              << cell.robot.name << " through " << driver << ", each after it ran in simulation. Type yes to go on: "
              << std::flush;
    std::string answer;
    std::getline(std::cin, answer);
    if (answer != "yes")
      return std::cerr << "demo: relay: not confirmed; nothing sent\n", 1;
  }
  const auto model = vrrw_kinematics::RobotModel::fromUrdf(cell.urdf);
  std::vector<double> max_velocity;
  for (const std::string& joint : joints)
    max_velocity.push_back(model.joints()[std::size_t(model.jointIndex(joint))].max_velocity);

  std::vector<Relayed> relayed;
  ros::Duration(0.5).sleep();  // the controller adopts the real arm's state from the driver's joint_states
  const auto from = relay.measured(joints);
  if (!from)
    return std::cerr << "demo: relay: no /" << cell.robot.name << "/joint_states with the arm's joints\n", 1;
  const std::vector<double> start = vrrw_demos::stateAt(track, instructions.front().start).positions;
  relayed.push_back(relay.arm("to_the_recorded_start", approach(joints, *from, start, max_velocity)));
  progress(relayed.back());
  std::size_t gripper_goal = 0;
  for (const Segment& instruction : instructions)
  {
    if (relayed.back().state != "SUCCEEDED")
      break;
    if (isGripperInstruction(instruction.name))
    {
      const vrrw_demos::GripperGoal& goal = track.gripper_goals[std::min(gripper_goal++, track.gripper_goals.size() - 1)];
      relayed.push_back(relay.gripper(instruction.name, goal.position, goal.max_effort));
    }
    else
    {
      const vrrw_trajectory::JointTrajectory motion = instructionGoal(track, instruction.start, instruction.end);
      relay.waitUntilAt(joints, motion.points.front().positions, 0.005, 2.0);
      relayed.push_back(relay.arm(instruction.name, motion));
    }
    progress(relayed.back());
  }
  const std::size_t expected = kInstructions.size() + 1, succeeded = std::count_if(
      relayed.begin(), relayed.end(), [](const Relayed& r) { return r.state == "SUCCEEDED"; });
  std::ofstream json(out);
  json << "{\"driver_action\": " << jsonString(driver) << ", \"confirmed\": " << jsonString(yes ? "--yes" : "typed yes")
       << ",\n \"instructions\": [";
  for (std::size_t i = 0; i < relayed.size(); ++i)
  {
    const Relayed& r = relayed[i];
    json << (i ? ",\n   " : "") << "{\"name\": " << jsonString(r.name) << ", \"kind\": " << jsonString(r.kind)
         << ", \"points\": " << r.points << ", \"seconds\": " << r.seconds << ", \"state\": " << jsonString(r.state)
         << ", \"message\": " << jsonString(r.message) << "}";
  }
  json << "],\n \"succeeded\": " << succeeded << ", \"expected\": " << expected << "}\n";
  progress(std::to_string(succeeded) + " of " + std::to_string(expected) + " goals succeeded (arm goals through " +
           driver + "); " + out);
  return succeeded == expected ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "demo_relay", ros::init_options::AnonymousName);
  try
  {
    const vrrw_common::Options options(argc, argv, 1, { "scene", "bag", "out" }, { "yes" });
    options.expectPositional({});
    return run(options.text("scene"), options.text("bag"), options.text("out", "relay.json"), options.flag("yes"));
  }
  catch (const vrrw_common::OptionError& e)
  {
    return std::cerr << "demo_relay: " << e.what() << " (usage: demo_relay --scene S --bag BAG [--out relay.json] [--yes])\n", 2;
  }
}
