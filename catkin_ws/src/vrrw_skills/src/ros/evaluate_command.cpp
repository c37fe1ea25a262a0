#include "evaluate_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <set>
#include <thread>

#include <ros/ros.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/realtime_pacer.h>
#include <vrrw_physics/ros/lockstep_client.h>
#include <vrrw_scene/scene_loader.h>
#include <vrrw_skills/evaluation.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_yaml.h>
#include <vrrw_trajectory/trajectory_error.h>
#include <vrrw_trajectory/whole_file.h>

#include <vrrw_skills/ros/arm_services.h>
#include <vrrw_skills/ros/skill_trials.h>
#include "workspace_process.h"

namespace vrrw_skills
{
namespace
{
std::atomic<bool> stopping{ false };

void stopTrials(int)
{
  stopping = true;
  WorkspaceArm::interrupt();
}

std::string names(const std::vector<std::string>& list)
{
  std::string out;
  for (const std::string& name : list)
    out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "none" : out;
}

/// The scene's objects; throws SkillError naming the scene when it lacks the robot, the object or the place.
std::set<std::string> checkScene(const std::string& scene_name, const std::string& robot, const std::string& object,
                                 const std::string& place_on)
{
  vrrw_scene::Scene scene;
  try
  {
    scene = vrrw_scene::loadScene(scene_name);
  }
  catch (const std::exception& e)
  {
    throw SkillError(std::string("--scene: ") + e.what());
  }
  std::vector<std::string> robots, objects;
  for (const auto& r : scene.robots)
    robots.push_back(r.name);
  std::set<std::string> obstacles;
  for (const auto& o : scene.objects)
  {
    objects.push_back(o.name);
    obstacles.insert(o.name);
  }
  if (std::find(robots.begin(), robots.end(), robot) == robots.end())
    throw SkillError(scene_name + ": robots: no robot '" + robot + "' (the scene has: " + names(robots) + ")");
  for (const std::string& needed : { object, place_on })
    if (!needed.empty() && !obstacles.count(needed))
      throw SkillError(scene_name + ": objects: no object '" + needed + "' (the scene has: " + names(objects) + ")");
  return obstacles;
}

EvaluationOptions evaluationOptions(const vrrw_common::Options& options)
{
  EvaluationOptions out;
  out.trials = options.count("trials", out.trials, 1, EvaluationOptions::kMaxTrials);
  out.seed = options.count("seed", out.seed, 0, vrrw_common::Options::kMaxCount);
  if (options.has("spread"))
  {
    const auto spread = options.list("spread", 3, vrrw_common::Range::closed(0.0, 1e3));
    if (spread[2] > 180.0)
      throw vrrw_common::OptionError("--spread: a yaw spread of " + std::to_string(spread[2]) +
                                     " deg is more than 180 deg");
    out.spread = { spread[0], spread[1], spread[2] * M_PI / 180.0 };
  }
  return out;
}

/// Waits for the new workspace's master, the robot's scene parameters, its planning services and the physics
/// node; throws SkillRefusal with the log's trouble when it does not come up.
void waitForWorkspace(const WorkspaceProcess& workspace, const std::string& robot, double seconds)
{
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  auto waitUntil = [&](const std::function<bool()>& ready) {
    while (!ready())
    {
      if (!workspace.running() || std::chrono::steady_clock::now() > end || stopping)
        throw SkillRefusal("the workspace did not come up at " + workspace.masterUri() + workspace.trouble());
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
  };
  waitUntil([] { return ros::master::check(); });
  waitUntil([&robot] { return ros::param::has("/scene/robots/" + robot + "/arm_joints"); });
  for (const std::string& service : std::vector<std::string>{ "/" + robot + "/compute_ik", "/" + robot + "/check_path",
                                      "/" + robot + "/attach_object", "/physics/set_object_pose" })
    waitUntil([&service] { return ros::service::exists(service, false); });
}

void drawTopView(const std::string& directory)
{
  const pid_t child = ::fork();
  if (child == 0)
  {
    const std::string script = std::string(VRRW_SKILLS_SCRIPTS) + "/plot_evaluation.py";
    const char* argv[] = { "/usr/bin/python3", script.c_str(), directory.c_str(), nullptr };
    ::execv(argv[0], const_cast<char* const*>(argv));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    std::cerr << "skill evaluate: the top view could not be drawn (" << directory << "/tracks.json has its data)\n";
}

void writeReport(const EvaluationReport& report, const std::string& directory)
{
  try
  {
    vrrw_trajectory::writeWholeFile(directory + "/metrics.json", metricsJson(report));
    vrrw_trajectory::writeWholeFile(directory + "/tracks.json", tracksJson(report));
    vrrw_trajectory::writeWholeFile(directory + "/index.html", indexHtml(report));
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw SkillRefusal(e.what());
  }
  drawTopView(directory);
}
}  // namespace

int evaluateCommand(int argc, char** argv)
{
  const auto start = std::chrono::steady_clock::now();
  const vrrw_common::Options options(argc, argv, 2,
                                     { "scene", "robot", "object", "trials", "seed", "spread", "out", "rtf" });
  options.expectPositional({ "SKILL.yaml" });
  EvaluationReport report;
  report.options = evaluationOptions(options);
  const std::string skill_file = options.positional().front();
  const Skill skill = loadSkill(skill_file);
  report.skill_file = skill_file;
  report.scene = options.text("scene");
  report.robot = options.text("robot", skill.robot);
  report.taught_robot = skill.robot;
  report.object = options.text("object", skill.object);
  report.object_start = skill.object_start;
  report.object_end = skill.object_end;
  const std::set<std::string> obstacles = checkScene(report.scene, report.robot, report.object, skill.place_on);
  const std::string out = options.text("out", "skill_evaluation");
  const std::string rtf = options.text("rtf", "max");
  try
  {
    vrrw_physics::parseRealTimeFactor(rtf, "--rtf");
  }
  catch (const std::invalid_argument& e)
  {
    throw vrrw_common::OptionError(e.what());
  }
  const int port = workspacePort();
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (error)
    throw SkillError("--out " + out + ": cannot be created (" + error.message() + ")");

  std::signal(SIGINT, stopTrials);
  std::signal(SIGTERM, stopTrials);
  std::cout << "skill evaluate: bringing up " << report.scene << " in physics on its own master, port " << port
            << " (log " << out << "/workspace.log)" << std::endl;
  WorkspaceProcess workspace(report.scene, rtf, out + "/workspace.log", port);
  int ros_argc = 1;
  ros::init(ros_argc, argv, "skill_evaluate", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const vrrw_common::ToolNode node_registration;
  waitForWorkspace(workspace, report.robot, 90.0);
  ros::NodeHandle node;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  vrrw_common::PersistentServices services(vrrw_common::ServiceLimits{ 60.0, 60.0 });
  // the trials hold the simulation and step it through every motion (lockstep): the same seed, the same trials
  vrrw_physics::LockstepClient simulation(services);
  if (!simulation.waitForPhysics(60.0))
    throw SkillRefusal("the workspace's physics node does not answer /physics/step" + workspace.trouble());
  simulation.pause();
  WorkspaceArm arm(node, report.robot, services);
  arm.holdSimulation(simulation);
  arm.waitUntilReady(60.0);
  ArmServices kinematics(services, report.robot, arm.armJoints());
  SkillTrials trials(node, skill, arm, kinematics, services, report.object, obstacles);
  std::cout << "skill evaluate: " << report.options.trials << " trials of " << skill_file << " on " << report.robot
            << std::endl;
  const auto poses = evaluationPoses(skill, report.options);
  for (std::size_t k = 0; k < poses.size() && !stopping; ++k)
  {
    const std::string label = "skill evaluate: trial " + std::to_string(k + 1) + "/" + std::to_string(poses.size());
    auto progress = [&label](const std::string& line) { std::cout << label << ": " << line << std::endl; };
    report.trials.push_back(trials.trial(static_cast<int>(k + 1), poses[k], progress));
    const TrialResult& t = report.trials.back();
    std::printf("%s at (%.3f, %.3f, %.1f deg): %s%s%s\n", label.c_str(), t.x, t.y, t.yaw_deg,
                t.success ? "success" : "failed", t.reason.empty() ? "" : ": ", t.reason.c_str());
    std::fflush(stdout);
  }
  spinner.stop();
  report.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeReport(report, out);
  std::cout << "skill evaluate: " << report.successes() << " of " << report.trials.size() << " succeeded; report "
            << out << "/index.html\n" << summaryJson(report) << std::endl;
  return stopping ? 1 : 0;
}
}  // namespace vrrw_skills
