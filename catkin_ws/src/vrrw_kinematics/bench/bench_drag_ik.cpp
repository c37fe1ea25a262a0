// vrrw_bench_drag_ik: the operator drags a robot's tcp target (a ghost at 100 Hz): each target lies on a
// smooth random joint-space motion, each solve is Arm::solveCollisionFree seeded with the previous answer
// (max jump 0.5 rad) against the rest of the scene. --moving-others moves every other robot at each step
// too, so the collision checker is rebuilt for every solve. Last line: one JSON object.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <random>
#include <vrrw_kinematics/arm.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_scene/scene_loader.h>

#include <vrrw_common/options.h>

#include "bench_support.h"

using namespace vrrw_kinematics;

namespace
{
/// Joint values of a smooth random motion of `arm` at step `k`: a sine per joint around `centre`, kept
/// within the joint limits.
Eigen::VectorXd smoothMotion(const Arm& arm, const Eigen::VectorXd& centre, const Eigen::VectorXd& phase, long k)
{
  Eigen::VectorXd q = centre;
  for (Eigen::Index i = 0; i < q.size(); ++i)
  {
    q[i] += 0.4 * std::sin(0.01 * static_cast<double>(k) * (1.0 + 0.3 * static_cast<double>(i)) + phase[i]);
    if (!arm.bounds().continuous(static_cast<std::size_t>(i)))
      q[i] = std::clamp(q[i], arm.bounds().lower()[i], arm.bounds().upper()[i]);
  }
  return q;
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options args(argc, argv, 1, { "scene", "robot", "seed", "steps" }, { "moving-others" });
    const vrrw_scene::Scene scene = vrrw_scene::loadScene(args.text("scene"));
    CollisionWorld world = CollisionWorld::fromScene(scene);
    world.loadOrComputeAllowedCollisions(scene.cache_dir);
    const vrrw_scene::Robot* robot = scene.robot(args.text("robot", scene.robots.front().name));
    if (!robot)
      throw std::runtime_error("--robot " + args.text("robot") + ": not a robot of the scene");
    std::vector<Arm> arms;
    for (const vrrw_scene::Robot& r : scene.robots)
      arms.emplace_back(world, r);
    Arm& dragged = arms[static_cast<std::size_t>(robot - scene.robots.data())];
    const Eigen::VectorXd initial = initialState(world.model(), scene);
    std::mt19937_64 rng(static_cast<std::uint64_t>(args.count("seed", 1, 0, vrrw_common::Options::kMaxCount)));
    std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
    std::vector<Eigen::VectorXd> phases;
    for (const Arm& arm : arms)
      phases.push_back(Eigen::VectorXd::NullaryExpr(static_cast<Eigen::Index>(arm.size()), [&] { return angle(rng); }));
    const long steps = static_cast<long>(args.count("steps", 3000, 1, 100000000));
    IkOptions options;
    options.max_jump = 0.5;
    const std::size_t index = static_cast<std::size_t>(&dragged - arms.data());
    for (int draw = 0; draw < 1000 && dragged.check(smoothMotion(dragged, dragged.jointValues(initial), phases[index], 0),
                                                    initial).collision; ++draw)
      phases[index] = Eigen::VectorXd::NullaryExpr(static_cast<Eigen::Index>(dragged.size()), [&] { return angle(rng); });
    Eigen::VectorXd ghost = smoothMotion(dragged, dragged.jointValues(initial), phases[index], 0);
    std::vector<double> times_us, cpu_us;
    std::map<std::string, long> outcomes;
    for (long k = 0; k < steps; ++k)
    {
      Eigen::VectorXd state = initial;
      if (args.has("moving-others"))
        for (std::size_t a = 0; a < arms.size(); ++a)
          if (&arms[a] != &dragged)
            state = arms[a].withJointValues(state, smoothMotion(arms[a], arms[a].jointValues(initial), phases[a], k));
      const Eigen::VectorXd wanted = smoothMotion(dragged, dragged.jointValues(initial), phases[index], k);
      const Eigen::Isometry3d target = dragged.basePose(state) * dragged.ikSolver().chain().fk(wanted);
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = threadCpuSeconds();
      const IkResult result = dragged.solveCollisionFree(target, ghost, state, options);
      cpu_us.push_back(1e6 * (threadCpuSeconds() - cpu_start));
      times_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
      ++outcomes[errorCodeName(result.code)];
      if (result.success)
        ghost = result.q;
    }
    double mean = 0.0;
    for (const double t : times_us)
      mean += t / static_cast<double>(times_us.size());
    std::string counts;
    for (const auto& [name, count] : outcomes)
      counts += (counts.empty() ? "" : ", ") + ("\"" + name + "\": " + std::to_string(count));
    std::printf("{\"scene\": \"%s\", \"robot\": \"%s\", \"solver\": \"%s\", \"moving_others\": %s, \"steps\": %ld, "
                "\"mean_us\": %.3f, \"median_us\": %.3f, \"p99_us\": %.3f, \"median_cpu_us\": %.3f, \"p99_cpu_us\": %.3f, "
                "\"outcomes\": {%s}}\n",
                scene.name.c_str(), robot->name.c_str(), dragged.ikSolver().hasAnalytic() ? "ur_analytic" : "numeric",
                args.has("moving-others") ? "true" : "false", steps, mean, percentile(times_us, 50),
                percentile(times_us, 99), percentile(cpu_us, 50), percentile(cpu_us, 99), counts.c_str());
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_drag_ik: " << e.what() << "\n";
    std::printf("{\"error\": \"%s\"}\n", e.what());
    return 2;
  }
}
