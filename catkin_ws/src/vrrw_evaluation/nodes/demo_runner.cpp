// demo_runner: the stages of `./vrrw demo` against a running physics workspace (run_demo.py starts it).
//   demo_runner --scene S [--trials N] [--seed S] [--out DIR] [--shown N] [--capture CMD] [--check]
// --check only validates the scene (a robot with a gripper, a graspable object) and exits.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_evaluation/demo_cell.h>

#include "../src/ros/pick_place_demo.h"

using namespace vrrw_evaluation;

namespace
{
/// The command line into \a scene, \a options and \a check; throws vrrw_common::OptionError naming the option.
void parse(int argc, char** argv, std::string& scene, DemoOptions& options, bool& check)
{
  const vrrw_common::Options o(argc, argv, 1, { "scene", "trials", "seed", "out", "shown", "capture" }, { "check" });
  o.expectPositional({});
  scene = o.text("scene");
  options.trials = static_cast<int>(o.count("trials", static_cast<std::uint64_t>(options.trials), 0, 1000));
  options.seed = o.count("seed", options.seed, 0, UINT64_MAX);
  options.out = o.text("out", options.out);
  options.shown_trials = static_cast<int>(o.count("shown", static_cast<std::uint64_t>(options.shown_trials), 0, 1000));
  options.capture_command = o.text("capture", options.capture_command);
  check = o.flag("check");
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "demo_runner", ros::init_options::AnonymousName);
  std::string scene;
  DemoOptions options;
  bool check = false;
  try
  {
    parse(argc, argv, scene, options, check);
  }
  catch (const vrrw_common::OptionError& e)
  {
    return std::cerr << "demo_runner: " << e.what() << "\n", 2;
  }
  Cell cell;
  std::string error;
  if (!findCell(scene, cell, error))
    return std::cerr << "demo: " << error << "\n", 2;
  if (check)
    return std::printf("demo: %s: robot %s picks '%s'\n", scene.c_str(), cell.robot.name.c_str(), cell.object.c_str()), 0;

  const auto start = std::chrono::steady_clock::now();
  ros::NodeHandle node;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  // The runner holds the simulation and steps it through every motion (lockstep): the same seed moves the same way.
  vrrw_common::PersistentServices links;
  vrrw_physics::LockstepClient sim(links);
  WorkspaceClient client(node, cell.robot, cell.object, cell.obstacles, sim);
  if (!client.waitUntilReady(60.0, error))
    return spinner.stop(), std::cerr << "demo: " << error << "\n", 1;
  DemoReport report;
  report.scene = scene;
  report.seed = options.seed;
  // The teach stage is an operator's: ghost-drive through the interaction node.
  GhostOperator ghost(node, cell.robot.name, sim);
  if (!ghost.waitUntilReady(10.0, error))
    return spinner.stop(), std::cerr << "demo: " << error << ": the teach stage needs the ghost services\n", 1;
  HandOperator hand(node, cell.robot.name, sim);
  if (!hand.waitUntilReady(10.0, error))
    return spinner.stop(), std::cerr << "demo: " << error << ": the teach stage needs free-drive\n", 1;
  options.table = cell.table;
  PickPlaceDemo demo(node, client, ghost, hand, cell, options);
  auto stage = [&](const char* name, const std::function<bool()>& run) {
    std::printf("demo: %s ...\n", name);
    std::fflush(stdout);
    const auto stage_start = std::chrono::steady_clock::now();
    bool ok = false;
    try
    {
      ok = run();
    }
    catch (const std::exception& e)  // the simulation, a recorder or the skill trials failed under the stage
    {
      error = e.what();
    }
    report.stage_seconds[name] = secondsSince(stage_start);
    std::printf("demo: %s %s in %.1f s\n", name, ok ? "done" : "FAILED", report.stage_seconds[name]);
    return ok;
  };
  bool ok = stage("1 teach", [&] { return demo.teach(report, error); });
  if (ok)
    ok = stage("2 segment", [&] {
      if (!demo.segment(report, error))
        return false;
      for (const Segment& s : report.segments)
        std::printf("demo:   %-18s %7.3f .. %7.3f s\n", s.name.c_str(), s.start, s.end);
      return true;
    });
  if (ok)
    ok = stage("3 replay", [&] { return demo.replay(report, error); });
  if (ok)
    ok = stage("4 generalize", [&] {
      demo.generalize(report);
      return true;
    });
  report.physics_rtf = client.realTimeFactor();
  report.wall_seconds = secondsSince(start);

  spinner.stop();  // no callback may run into the client while it is destroyed
  if (!ok)
    std::cerr << "demo: " << error << "\n";
  try
  {
    writeReport(report, options.out);
  }
  catch (const std::exception& e)
  {
    return std::cerr << "demo: " << e.what() << "\n", 1;
  }
  std::printf("demo: replay joint RMS %.2e rad, drill %.1f mm / %.2f deg; skill %d of %d trials succeeded, grasp "
              "%.2f mm / %.2f deg from the script's\n",
              report.replay_joint_rms_rad, report.replay_object_position_error_m * 1000,
              report.replay_object_angle_error_deg, report.successCount(), report.trialCount(),
              report.skill.grasp_error_mm, report.skill.grasp_error_deg);
  return ok ? 0 : 1;
}
