// vrrw_bench_physics --scene NAME [--seconds 10] [--dt 0.001] [--mode rigid] [--drives constraint|stable_pd]
// Steps a scene as fast as possible on one thread, every robot holding its initial pose against
// gravity; reports steps_per_s, real-time factor (wall clock, and CPU time of this process: the
// machine is shared) and the largest hold error. Last line: JSON.
#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
  std::string scene_name = "paper_multibot";
  double seconds = 10.0;
  vrrw_physics::WorldOptions options;
  std::string mode = "rigid";
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (i + 1 >= argc)
    {
      std::cerr << "vrrw_bench_physics: " << arg << ": missing value\n";
      return 2;
    }
    const std::string value = argv[++i];
    try
    {
      if (arg == "--scene")
        scene_name = value;
      else if (arg == "--seconds")
        seconds = std::stod(value);
      else if (arg == "--dt")
        options.dt = std::stod(value);
      else if (arg == "--mode")
        mode = value;
      else if (arg == "--iterations")
        options.solver_iterations = std::stoi(value);
      else if (arg == "--inner")
        options.solver_inner_iterations = std::stoi(value);
      else if (arg == "--residual")
        options.solver_residual = std::stod(value);
      else if (arg == "--drives" && (value == "constraint" || value == "stable_pd"))
        options.drive_scheme =
            value == "constraint" ? vrrw_physics::DriveScheme::Constraint : vrrw_physics::DriveScheme::StablePd;
      else
      {
        std::cerr << "vrrw_bench_physics: unknown option " << arg
                  << " (--scene NAME --seconds S --dt DT --mode rigid|compliant --iterations N "
                     "--inner N --residual R --drives constraint|stable_pd)\n";
        return 2;
      }
    }
    catch (const std::exception&)
    {
      std::cerr << "vrrw_bench_physics: " << arg << ": not a number: " << value << "\n";
      return 2;
    }
  }
  try
  {
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(scene_name);
    vrrw_physics::PhysicsWorld world(scene, options);
    int dofs = 0;
    std::vector<std::vector<double>> hold;
    for (const std::string& robot : world.robotNames())
    {
      world.setMode(robot, vrrw_physics::parseDriveMode(mode));
      hold.push_back(world.jointStates(robot).position);
      dofs += int(hold.back().size());
    }
    const long steps = std::lround(seconds / options.dt);
    int rejected = 0;
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i)
    {
      if (!world.step())
        ++rejected;
      if ((i + 1) % 2000 == 0)
        std::cerr << "t=" << world.time() << " s\r";
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
    std::cerr << "\n";
    std::printf("{\"bench\": \"physics\", \"scene\": \"%s\", \"mode\": \"%s\", \"drives\": \"%s\", \"dt\": %g, \"sim_seconds\": %g, "
                "\"robots\": %zu, \"objects\": %zu, \"dofs\": %d, \"solver_iterations\": %d, \"steps\": %ld, "
                "\"wall_seconds\": %.3f, \"cpu_seconds\": %.3f, \"steps_per_s\": %.1f, \"rtf\": %.2f, \"rtf_cpu\": %.2f, "
                "\"max_hold_error_rad\": %.3g, "
                "\"guard_rejections\": %d}\n",
                scene.name.c_str(), mode.c_str(),
                options.drive_scheme == vrrw_physics::DriveScheme::Constraint ? "constraint" : "stable_pd", options.dt, world.time(), names.size(), world.objectNames().size(),
                dofs, options.solver_iterations, steps, wall, cpu, steps / wall, world.time() / wall, world.time() / cpu, max_error,
                rejected);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_physics: " << e.what() << "\n";
    return 1;
  }
}
