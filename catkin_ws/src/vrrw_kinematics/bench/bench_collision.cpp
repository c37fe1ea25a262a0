// vrrw_bench_collision: full-scene state checks per second for each robot's arm (the other robots at
// their initial states, ACM from the scene cache). Last line: one JSON object.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>
#include <sstream>
#include <vrrw_scene/scene_loader.h>

#include <vrrw_common/options.h>

#include "bench_support.h"
#include "vrrw_kinematics/scene_state.h"
#include "vrrw_kinematics/state_checker.h"


int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options args(argc, argv, 1, { "samples", "scene", "robot", "seed" }, {});
    const long samples = static_cast<long>(args.count("samples", 200000, 1, 100000000));
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(args.text("scene"));
    vrrw_kinematics::CollisionWorld world = vrrw_kinematics::CollisionWorld::fromScene(scene);
    const auto acm_start = std::chrono::steady_clock::now();
    const bool cached = world.loadOrComputeAllowedCollisions(scene.cache_dir);
    const double acm_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - acm_start).count();
    const Eigen::VectorXd initial = vrrw_kinematics::initialState(world.model(), scene);
    std::ostringstream robots;
    double first_rate = 0.0;
    for (const vrrw_scene::Robot& robot : scene.robots)
    {
      if (args.has("robot") && args.text("robot") != robot.name)
        continue;
      vrrw_kinematics::StateChecker checker(world, robot.arm_joints, initial);
      std::mt19937_64 rng(static_cast<std::uint64_t>(args.count("seed", 1, 0, vrrw_common::Options::kMaxCount)));
      std::vector<Eigen::VectorXd> states;
      for (long s = 0; s < std::min(samples, 20000L); ++s)
      {
        Eigen::VectorXd q(robot.arm_joints.size());
        for (std::size_t i = 0; i < robot.arm_joints.size(); ++i)
        {
          const auto& joint = world.model().joints()[world.model().jointIndex(robot.arm_joints[i])];
          q[i] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
        }
        states.push_back(q);
      }
      long in_collision = 0;
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = vrrw_kinematics::threadCpuSeconds();
      for (long s = 0; s < samples; ++s)
        in_collision += checker.valid(states[static_cast<std::size_t>(s) % states.size()]) ? 0 : 1;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double cpu_rate = static_cast<double>(samples) / (vrrw_kinematics::threadCpuSeconds() - cpu_start);
      const double rate = static_cast<double>(samples) / seconds;
      std::vector<Eigen::VectorXd> free_states;
      for (const Eigen::VectorXd& q : states)
        if (checker.valid(q))
          free_states.push_back(q);
      double free_rate = 0.0;
      if (!free_states.empty())
      {
        const auto free_start = std::chrono::steady_clock::now();
        long free_valid = 0;
        for (long s = 0; s < samples; ++s)
          free_valid += checker.valid(free_states[static_cast<std::size_t>(s) % free_states.size()]) ? 1 : 0;
        free_rate = static_cast<double>(samples) /
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - free_start).count();
        if (free_valid != samples)
          throw std::runtime_error("checker is not deterministic");
      }
      if (first_rate == 0.0)
        first_rate = rate;
      std::cerr << robot.name << ": " << rate << " checks/s (" << free_rate << " on collision-free states), "
                << checker.pairCount() << " pairs\n";
      robots << (robots.tellp() > 0 ? ", " : "") << "\"" << robot.name << "\": {\"checks_per_s\": " << rate
             << ", \"cpu_checks_per_s\": " << cpu_rate << ", \"free_checks_per_s\": " << free_rate << ", \"collision_fraction\": " << static_cast<double>(in_collision) / static_cast<double>(samples)
             << ", \"pairs\": " << checker.pairCount() << "}";
    }
    std::printf("{\"scene\": \"%s\", \"samples\": %ld, \"checks_per_s\": %.0f, \"acm_entries\": %zu, "
                "\"acm_seconds\": %.3f, \"acm_cached\": %s, \"robots\": {%s}}\n",
                scene.name.c_str(), samples, first_rate, world.acm().size(), acm_s, cached ? "true" : "false",
                robots.str().c_str());
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_collision: " << e.what() << "\n";
    std::printf("{\"error\": \"%s\"}\n", e.what());
    return 2;
  }
}
