// vrrw_bench_physics: steps a scene as fast as possible on one thread, every robot holding its initial pose
// against gravity; reports steps_per_s, real-time factor (wall clock, and CPU time of this process: the
// machine is shared) and the largest hold error. Last line: JSON. --help for the options.
#include <vrrw_common/options.h>
#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <string>

namespace
{
const char* kUsage = R"(usage: vrrw_bench_physics [OPTIONS]   (./vrrw bench physics [OPTIONS])
Steps a scene on one thread as fast as it can, every robot holding its initial pose; prints the speed
(steps per second, real-time factor by wall clock and by CPU time) and the largest hold error. The last
line is JSON.
  --scene NAME|YAML       shipped scene or scene file (default paper_multibot)
  --seconds S             simulated seconds (default 10)
  --dt DT                 step (s, default 0.001)
  --mode rigid|compliant  drive mode of every arm (default rigid)
  --drives constraint|stable_pd   drive scheme (default constraint)
  --iterations N          most solver sweeps per step (default 30)
  --inner N               joint-row sweeps per sweep while a robot touches something (default 5)
  --residual R            solver stop threshold (default 1e-9)
  --help                  this text
)";

struct Settings
{
  std::string scene = "paper_multibot";
  double seconds = 10.0;
  vrrw_physics::WorldOptions options;
};

/// Reads the command line into `s`; false when --help was shown. Throws vrrw_common::OptionError.
bool parse(int argc, char** argv, Settings& s)
{
  const vrrw_common::Options o(argc, argv, 1,
                               { "scene", "seconds", "dt", "mode", "iterations", "inner", "residual", "drives" }, { "help" });
  if (o.flag("help") || (argc > 1 && std::string(argv[1]) == "-h"))
  {
    std::cout << kUsage;
    return false;
  }
  o.expectPositional({});
  s.scene = o.text("scene", s.scene);
  s.seconds = o.number("seconds", s.seconds, vrrw_common::Range::aboveUpTo(0.0, 3600.0));
  s.options.dt = o.number("dt", s.options.dt);
  if (o.has("mode"))
    s.options.mode = vrrw_physics::parseDriveMode(o.text("mode"));
  s.options.solver_iterations = static_cast<int>(o.count("iterations", s.options.solver_iterations, 1, 100000));
  s.options.solver_inner_iterations = static_cast<int>(o.count("inner", s.options.solver_inner_iterations, 0, 100000));
  s.options.solver_residual = o.number("residual", s.options.solver_residual);
  if (o.has("drives"))
    s.options.drive_scheme = vrrw_physics::parseDriveScheme(o.text("drives"));
  return true;
}
}  // namespace

int main(int argc, char** argv)
{
  Settings settings;
  try
  {
    if (!parse(argc, argv, settings))
      return 0;
  }
  catch (const std::exception& e)  // an option, or a drive mode or scheme parseDrive* does not know
  {
    std::cerr << "vrrw_bench_physics: " << e.what() << " (--help lists the options)\n";
    return 2;
  }
  const vrrw_physics::WorldOptions& options = settings.options;
  // Progress rewrites one line on a terminal; in a captured log every report is a line of its own.
  const char* progress_end = isatty(STDERR_FILENO) ? "\r" : "\n";
  try
  {
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(settings.scene);
    vrrw_physics::PhysicsWorld world(scene, options);
    int dofs = 0;
    std::vector<std::vector<double>> hold;
    for (const std::string& robot : world.robotNames())
    {
      hold.push_back(world.jointStates(robot).position);
      dofs += int(hold.back().size());
    }
    const long steps = std::lround(settings.seconds / options.dt);
    int rejected = 0;
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i)
    {
      if (!world.step())
        ++rejected;
      if ((i + 1) % 2000 == 0)
        std::cerr << "t=" << world.time() << " s" << progress_end;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    double max_error = 0.0;
    const auto names = world.robotNames();
    for (std::size_t r = 0; r < names.size(); ++r)
    {
      const auto state = world.jointStates(names[r]);
      const auto& joints = world.robot(names[r]).joints();
      for (std::size_t j = 0; j < state.position.size(); ++j)
        if (joints[j].drive >= 0)
          max_error = std::max(max_error, std::abs(state.position[j] - hold[r][j]));
    }
    if (isatty(STDERR_FILENO))
      std::cerr << "\n";
    std::printf("{\"bench\": \"physics\", \"scene\": \"%s\", \"mode\": \"%s\", \"drives\": \"%s\", \"dt\": %g, "
                "\"sim_seconds\": %g, \"robots\": %zu, \"objects\": %zu, \"dofs\": %d, \"solver_iterations\": %d, "
                "\"steps\": %ld, \"wall_seconds\": %.3f, \"cpu_seconds\": %.3f, \"steps_per_s\": %.1f, \"rtf\": %.2f, "
                "\"rtf_cpu\": %.2f, \"max_hold_error_rad\": %.3g, \"guard_rejections\": %d}\n",
                scene.name.c_str(), vrrw_physics::toString(options.mode),
                options.drive_scheme == vrrw_physics::DriveScheme::Constraint ? "constraint" : "stable_pd", options.dt,
                world.time(), names.size(), world.objectNames().size(), dofs, options.solver_iterations, steps, wall,
                cpu, steps / wall, world.time() / wall, world.time() / cpu, max_error, rejected);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_physics: " << e.what() << "\n";
    return 1;
  }
}
