// vrrw_bench_plan: random collision-free start/goal pairs for each arm of a scene (other robots at their
// initial states), planned with OMPL and time-parameterized. Last line: one JSON object.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <ompl/util/RandomNumbers.h>
#include <random>
#include <sstream>
#include <vrrw_scene/scene_loader.h>

#include <vrrw_common/options.h>

#include "bench_support.h"
#include "vrrw_kinematics/motion_planner.h"
#include "vrrw_kinematics/scene_state.h"
#include "vrrw_kinematics/time_parameterization.h"


namespace
{
/// A collision-free state within the joint limits and within pi of the initial state on every joint: joints
/// with +-2 pi limits otherwise give pairs in different connected components (a UR's shoulder past the table).
Eigen::VectorXd randomValid(vrrw_kinematics::MotionPlanner& planner, const Eigen::VectorXd& initial,
                            std::mt19937_64& rng)
{
  Eigen::VectorXd q(static_cast<Eigen::Index>(planner.size()));
  const Eigen::VectorXd low = planner.lowerLimits().cwiseMax((initial.array() - M_PI).matrix());
  const Eigen::VectorXd high = planner.upperLimits().cwiseMin((initial.array() + M_PI).matrix());
  for (int attempt = 0; attempt < 100000; ++attempt)
  {
    for (Eigen::Index i = 0; i < q.size(); ++i)
      q[i] = std::uniform_real_distribution<double>(low[i], high[i])(rng);
    if (planner.stateValid(q))
      return q;
  }
  throw std::runtime_error("no collision-free state found in 100000 samples");
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options args(argc, argv, 1, { "queries", "seed", "scene", "robot", "planner", "time-limit", "shortcuts" }, { "verbose" });
    const long queries = static_cast<long>(args.count("queries", 100, 1, 100000000));
    const auto seed = static_cast<std::uint64_t>(args.count("seed", 1, 0, vrrw_common::Options::kMaxCount));
    ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(args.text("scene"));
    vrrw_kinematics::CollisionWorld world = vrrw_kinematics::CollisionWorld::fromScene(scene);
    world.loadOrComputeAllowedCollisions(scene.cache_dir);
    const Eigen::VectorXd initial = vrrw_kinematics::initialState(world.model(), scene);
    std::vector<double> all_ms, all_cpu_ms, all_timing_ms;
    long successes = 0, total = 0;
    double length_sum = 0.0, duration_sum = 0.0;
    std::ostringstream robots;
    for (const vrrw_scene::Robot& robot : scene.robots)
    {
      if (args.has("robot") && args.text("robot") != robot.name)
        continue;
      vrrw_kinematics::MotionPlanner planner(world, robot.arm_joints, robot.tcp_link, initial);
      vrrw_kinematics::TimingOptions timing;
      for (const std::string& joint : robot.arm_joints)
        timing.max_velocity.push_back(world.model().joints()[world.model().jointIndex(joint)].max_velocity);
      timing.max_acceleration = vrrw_kinematics::armAccelerationLimits(robot);
      const vrrw_kinematics::TimeParameterization parameterization(timing);
      std::mt19937_64 rng(seed);
      Eigen::VectorXd home(static_cast<Eigen::Index>(robot.arm_joints.size()));
      for (std::size_t i = 0; i < robot.arm_joints.size(); ++i)
        home[static_cast<Eigen::Index>(i)] = initial[world.model().variableIndex(robot.arm_joints[i])];
      std::vector<double> ms;
      long robot_successes = 0;
      for (long query = 0; query < queries; ++query)
      {
        vrrw_kinematics::PlanRequest request;
        request.start = randomValid(planner, home, rng);
        request.goal_joints = randomValid(planner, home, rng);
        request.planner = args.text("planner", "RRTConnect");
        request.time_limit = args.number("time-limit", 1.0);
        request.seed = seed + static_cast<std::uint64_t>(query);
        request.shortcut_attempts = static_cast<int>(static_cast<long>(args.count("shortcuts", 0, 0, 100000)));
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = vrrw_kinematics::threadCpuSeconds();
        const vrrw_kinematics::PlanResult result = planner.plan(request);
        all_cpu_ms.push_back(1e3 * (vrrw_kinematics::threadCpuSeconds() - cpu_start));
        const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        ms.push_back(elapsed);
        all_ms.push_back(elapsed);
        ++total;
        if (args.has("verbose"))
          std::cerr << robot.name << " query " << query << ": " << elapsed << " ms " << result.message << "\n";
        if (!result.success)
        {
          std::cerr << robot.name << " query " << query << ": " << result.message << "\n";
          continue;
        }
        const auto timing_start = std::chrono::steady_clock::now();
        const auto trajectory = parameterization.compute(result.path, robot.arm_joints);
        all_timing_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - timing_start).count());
        ++robot_successes;
        length_sum += result.path_length;
        duration_sum += trajectory.duration();
      }
      successes += robot_successes;
      std::cerr << robot.name << ": " << robot_successes << "/" << queries << " median "
                << vrrw_kinematics::percentile(ms, 50) << " ms, p95 " << vrrw_kinematics::percentile(ms, 95) << " ms\n";
      robots << (robots.tellp() > 0 ? ", " : "") << "\"" << robot.name << "\": {\"success_rate\": "
             << static_cast<double>(robot_successes) / static_cast<double>(queries)
             << ", \"median_ms\": " << vrrw_kinematics::percentile(ms, 50)
             << ", \"p95_ms\": " << vrrw_kinematics::percentile(ms, 95) << "}";
    }
    const double n_ok = static_cast<double>(std::max(1L, successes));
    std::printf("{\"scene\": \"%s\", \"planner\": \"%s\", \"queries\": %ld, \"success_rate\": %.4f, "
                "\"median_ms\": %.3f, \"p95_ms\": %.3f, \"median_cpu_ms\": %.3f, \"p95_cpu_ms\": %.3f, "
                "\"mean_path_length\": %.4f, \"mean_duration_s\": %.4f, "
                "\"timing_median_ms\": %.3f, \"robots\": {%s}}\n",
                scene.name.c_str(), args.text("planner", "RRTConnect").c_str(), total,
                static_cast<double>(successes) / static_cast<double>(std::max(1L, total)),
                vrrw_kinematics::percentile(all_ms, 50), vrrw_kinematics::percentile(all_ms, 95),
                vrrw_kinematics::percentile(all_cpu_ms, 50), vrrw_kinematics::percentile(all_cpu_ms, 95), length_sum / n_ok,
                duration_sum / n_ok, vrrw_kinematics::percentile(all_timing_ms, 50), robots.str().c_str());
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_plan: " << e.what() << "\n";
    std::printf("{\"error\": \"%s\"}\n", e.what());
    return 2;
  }
}
