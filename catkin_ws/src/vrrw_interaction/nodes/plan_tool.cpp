// vrrw_plan (./vrrw plan): plans a motion of a running workspace's robot through /<robot>/plan to joint values,
// a pose or one of the robot's presets (the ghost's), prints what it is in one line (duration, points, the
// fastest joint) and keeps it as a CSV for `./vrrw send ROBOT --csv FILE`.
// Exit codes: 0 planned, 1 failed while running, 2 bad input.
#include <iostream>
#include <ros/ros.h>
#include <sys/stat.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_control/ros/arm_client.h>
#include <vrrw_interaction/presets.h>
#include <vrrw_scene/scene_loader.h>
#include <vrrw_trajectory/csv.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace
{
using vrrw_common::OptionError;

const char* const kUsage =
    "usage: vrrw_plan ROBOT --joints q1,..,qn | --pose x,y,z,qx,qy,qz,qw [--frame F] | --preset NAME\n"
    "                 [--seed N] [--out FILE.csv]\n";

/// The preset \a name of \a robot: the model's (urdf/config/presets.yaml) or its scene's, as the ghost has them.
std::vector<double> preset(const std::string& robot, const std::string& name, std::size_t joints)
{
  std::string model, scene_file;
  ros::param::get("/scene/robots/" + robot + "/model", model);
  ros::param::get("/scene/file", scene_file);
  const auto presets = vrrw_interaction::Presets::load(vrrw_scene::vrrwRoot() + "/urdf/config/presets.yaml", model,
                                                       scene_file, robot, joints);
  const Eigen::VectorXd& q = presets.at(name);
  return { q.data(), q.data() + q.size() };
}

int run(int argc, char** argv)
{
  const vrrw_common::Options o(argc, argv, 1, { "joints", "pose", "frame", "preset", "seed", "out" });
  o.expectPositional({ "ROBOT" });
  const std::string robot = o.positional()[0], goal = o.oneOf({ "joints", "pose", "preset" });
  o.count("seed", 0, 0, UINT64_MAX);
  const std::string out = o.text("out", "");
  struct stat existing;
  if (!out.empty() && ::stat(out.c_str(), &existing) == 0)
    throw OptionError("--out: " + out + ": exists; not overwritten");
  vrrw_common::checkWorkspace({ robot, {}, { "/" + robot + "/plan" } });
  ros::AsyncSpinner spinner(1);  // after the check: its NodeHandle would wait for a master forever
  spinner.start();
  vrrw_control::ArmClient arm(robot, std::cout);
  vrrw_msgs::Plan::Request request;
  if (goal == "preset")
  {
    request.goal_joints.name = arm.armJoints();
    request.goal_joints.position = preset(robot, o.text("preset"), arm.armJoints().size());
    request.seed = o.count("seed", 0, 0, UINT64_MAX);
  }
  else
    request = vrrw_control::planRequest(o, arm.armJoints());
  const auto trajectory = arm.plan(request);
  if (!out.empty())
  {
    vrrw_trajectory::writeCsv(out, vrrw_trajectory::fromMsg(trajectory));
    std::cout << "written: " << out << " (./vrrw send " << robot << " --csv " << out << " executes it)" << std::endl;
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "vrrw_plan", ros::init_options::AnonymousName);
  const vrrw_common::ToolNode node_registration;
  try
  {
    return run(argc, argv);
  }
  catch (const OptionError& e)
  {
    std::cerr << "vrrw_plan: " << e.what() << "\n" << kUsage;
    return 2;
  }
  catch (const std::exception& e)  // the workspace, the planner, a preset, the CSV: one line each
  {
    std::cerr << "vrrw_plan: " << e.what() << "\n";
    return 1;
  }
}
