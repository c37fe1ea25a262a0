// demo_relay: stage 5 of `./vrrw demo --real NS`: the demonstration's instructions through the controller's
// real relay, on the robot's master.
//   demo_relay --scene S --bag BAG --out relay.json [--yes]
// Beside the real driver runs a vrrw controller in real mode for the scene's robot (run_demo.py starts it).
// Each arm instruction is the goal stage 3 replayed (the recorded samples between the bag's annotations),
// sent through vrrw_demos' one real-mode goal path (RobotControllers: the controller simulates it, it is
// confirmed, the driver runs it). Gripper goals run in simulation only (a real gripper has its own driver).
// Without --yes the operator types yes.
#include <algorithm>
#include <csignal>
#include <fstream>
#include <iostream>

#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_demos/approach_move.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/ros/robot_controllers.h>
#include <vrrw_evaluation/demo_cell.h>
#include <vrrw_evaluation/demo_report.h>
#include <vrrw_evaluation/pick_place_task.h>
#include <vrrw_kinematics/robot_model.h>

#include <vrrw_demos/ros/demo_bag.h>
#include <vrrw_evaluation/annotations.h>
#include <vrrw_evaluation/joint_paths.h>

using namespace vrrw_evaluation;

namespace
{
/// Set by SIGINT / SIGTERM: the running goal is cancelled (on the real arm too).
std::atomic<bool> g_interrupted{ false };

struct Relayed
{
  std::string name, kind;
  vrrw_demos::GoalOutcome outcome;
  std::size_t points = 0;
  double seconds = 0.0;
};

void progress(const std::string& line)
{
  std::cout << "demo: relay: " << line << std::endl;
}

void writeJson(const std::string& out, const std::string& driver, bool yes, const std::vector<Relayed>& relayed,
               std::size_t succeeded, std::size_t expected)
{
  std::ofstream json(out);
  json << "{\"driver_action\": " << jsonString(driver) << ", \"confirmed\": " << jsonString(yes ? "--yes" : "typed yes")
       << ",\n \"instructions\": [";
  for (std::size_t i = 0; i < relayed.size(); ++i)
  {
    const Relayed& r = relayed[i];
    json << (i ? ",\n   " : "") << "{\"name\": " << jsonString(r.name) << ", \"kind\": " << jsonString(r.kind)
         << ", \"points\": " << r.points << ", \"seconds\": " << r.seconds << ", \"state\": "
         << jsonString(r.outcome.state) << ", \"error_code\": " << r.outcome.error_code
         << ", \"message\": " << jsonString(r.outcome.message) << "}";
  }
  json << "],\n \"succeeded\": " << succeeded << ", \"expected\": " << expected << "}\n";
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
  std::string mode;  // roslaunch sets it as the controller starts
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(15.0);
       !node.getParam("/" + cell.robot.name + "/controller/mode", mode) && ros::WallTime::now() < end;)
    ros::WallDuration(0.1).sleep();
  if (mode != "real")
    return std::cerr << "demo: relay: /" << cell.robot.name << "/controller/mode is '" << mode
                     << "', not real: no real relay runs\n", 1;
  const std::string driver = node.param<std::string>("/" + cell.robot.name + "/controller/real_driver_action", "");
  vrrw_demos::RobotControllers controllers(cell.robot.name, true, &g_interrupted);
  controllers.connect(15.0);
  if (!yes && !vrrw_demos::operatorSaysYes("demo: relay: the demonstration's " + std::to_string(kInstructions.size()) +
                                               " instructions will move the REAL robot " + cell.robot.name + " through " +
                                               driver + ", each after it ran in simulation.",
                                           std::cin, std::cout))
    return std::cerr << "demo: relay: not confirmed; nothing sent\n", 1;
  const auto model = vrrw_kinematics::RobotModel::fromUrdf(cell.urdf);
  std::vector<double> max_velocity;
  for (const std::string& joint : joints)
    max_velocity.push_back(model.joints()[std::size_t(model.jointIndex(joint))].max_velocity);

  // To the recorded start (as vrrw_demos' replay starts), then each instruction as stage 3 replayed it.
  ros::Duration(0.5).sleep();  // the controller adopts the real arm's state from the driver's joint_states
  const auto from = controllers.measuredArm(joints, 5.0);
  const auto arm = [&](const std::string& name, const vrrw_trajectory::JointTrajectory& motion) {
    const auto outcome = controllers.runArm({ name, motion, ros::Time(), {} }, 60.0);
    return Relayed{ name, "arm", outcome, motion.points.size(), motion.duration() };
  };
  std::vector<Relayed> relayed{ arm("to_the_recorded_start",
                                    vrrw_demos::approachMove(joints, from, vrrw_demos::stateAt(track, instructions.front().start).positions,
                                                             max_velocity)) };
  progress(relayed.back().name + ": " + relayed.back().outcome.text() + " (arm)");
  std::size_t gripper_goal = 0;
  for (const Segment& instruction : instructions)
  {
    if (!relayed.back().outcome.succeeded())
      break;
    if (isGripperInstruction(instruction.name))
    {
      const vrrw_demos::GripperGoal& goal = track.gripper_goals[std::min(gripper_goal++, track.gripper_goals.size() - 1)];
      relayed.push_back({ instruction.name, "gripper (simulated only)",
                          controllers.runGripper(goal.position, goal.max_effort, 10.0), 1, 0.0 });
    }
    else
    {
      const vrrw_trajectory::JointTrajectory motion = instructionGoal(track, instruction.start, instruction.end);
      // the driver's joint_states may trail its result, and the gate checks a goal's start against them
      controllers.waitUntilAt(joints, motion.points.front().positions, 0.005, 2.0);
      relayed.push_back(arm(instruction.name, motion));
    }
    progress(relayed.back().name + ": " + relayed.back().outcome.text() + " (" + relayed.back().kind + ")");
  }
  const std::size_t expected = kInstructions.size() + 1, succeeded = std::count_if(
      relayed.begin(), relayed.end(), [](const Relayed& r) { return r.outcome.succeeded(); });
  writeJson(out, driver, yes, relayed, succeeded, expected);
  progress(std::to_string(succeeded) + " of " + std::to_string(expected) + " goals succeeded (arm goals through " +
           driver + "); " + out);
  return succeeded == expected ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "demo_relay", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  std::signal(SIGINT, [](int) { g_interrupted = true; });
  std::signal(SIGTERM, [](int) { g_interrupted = true; });
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
  catch (const std::exception& e)  // the bag (runtime_error), the controllers (vrrw_demos::DemoError)
  {
    std::cerr << "demo: relay: " << e.what() << "\n";
    return 1;
  }
}
