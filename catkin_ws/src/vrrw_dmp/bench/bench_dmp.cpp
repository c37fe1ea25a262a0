// vrrw_bench_dmp: median learn and rollout times of a DMP; progress on stderr, last line JSON.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>

#include <vrrw_dmp/dmp.h>

#include <vrrw_common/options.h>

namespace
{
using Clock = std::chrono::steady_clock;

/// A jittery recording of a smooth reach: minimum jerk plus a bump, per joint a different amplitude.
vrrw_trajectory::JointTrajectory syntheticDemo(std::size_t samples, std::size_t dofs)
{
  std::mt19937 random(42);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const double duration = 3.0;
  vrrw_trajectory::JointTrajectory demo;
  for (std::size_t j = 0; j < dofs; ++j)
    demo.joint_names.push_back("joint_" + std::to_string(j + 1));
  for (std::size_t k = 0; k < samples; ++k)
  {
    double u = static_cast<double>(k) / static_cast<double>(samples - 1);
    if (k > 0 && k + 1 < samples)
      u += jitter(random) / static_cast<double>(samples - 1);
    vrrw_trajectory::TrajectoryPoint point;
    point.time = u * duration;
    for (std::size_t j = 0; j < dofs; ++j)
    {
      const double a = 0.3 + 0.1 * static_cast<double>(j);
      const double reach = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
      point.positions.push_back(a * reach + 0.2 * std::pow(std::sin(M_PI * u), 2) * std::sin(2.0 * M_PI * u));
      point.velocities.push_back(0.0);
    }
    demo.points.push_back(std::move(point));
  }
  return demo;
}

template <typename Action>
double medianMicroseconds(std::size_t repetitions, Action&& action)
{
  std::vector<double> times;
  times.reserve(repetitions);
  for (std::size_t r = 0; r < repetitions; ++r)
  {
    const auto start = Clock::now();
    action();
    times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  return times[times.size() / 2];
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const vrrw_common::Options options(argc, argv, 1, { "samples", "dofs", "basis", "steps", "repetitions" });
    const std::size_t samples = options.count("samples", 1000, 0, 1000000000);
    const std::size_t dofs = options.count("dofs", 6, 0, 1000000000);
    const std::size_t basis = options.count("basis", 50, 0, 1000000000);
    const std::size_t steps = options.count("steps", 1000, 0, 1000000000);
    const std::size_t repetitions = options.count("repetitions", 301, 0, 1000000000);
    if (samples < 3 || dofs == 0 || basis == 0 || steps == 0 || repetitions == 0)
      throw vrrw_common::OptionError("need --samples >= 3, --dofs, --basis, --steps, --repetitions >= 1");

    const auto demo = syntheticDemo(samples, dofs);
    vrrw_dmp::DmpParameters parameters;
    parameters.basis_count = basis;
    std::cerr << "vrrw_bench_dmp: " << samples << " samples, " << dofs << " dofs, " << basis << " basis, "
              << repetitions << " repetitions\n";

    volatile double sink = 0.0;
    const double learn_us = medianMicroseconds(repetitions, [&] {
      sink = sink + vrrw_dmp::Dmp::learn(demo, parameters).weights()[0][0];
    });
    std::cerr << "  learn: median " << learn_us << " us\n";

    const auto dmp = vrrw_dmp::Dmp::learn(demo, parameters);
    const double dt = dmp.demoDuration() / static_cast<double>(steps);
    std::vector<double> goal = dmp.demoGoal();
    for (double& g : goal)
      g += 0.25;
    const vrrw_dmp::DmpState initial = dmp.begin(dmp.demoStart(), goal, dmp.demoDuration());
    vrrw_dmp::DmpState state = initial;
    std::vector<double> positions((steps + 1) * dofs);
    const double rollout_us = medianMicroseconds(repetitions, [&] {
      state = initial;
      std::copy(state.positions.begin(), state.positions.end(), positions.begin());
      for (std::size_t k = 1; k <= steps; ++k)
      {
        dmp.step(state, dt);
        std::copy(state.positions.begin(), state.positions.end(), positions.begin() + static_cast<long>(k * dofs));
      }
      sink = sink + positions.back();
    });
    std::cerr << "  rollout (" << steps << " steps of the allocation-free step()): median " << rollout_us << " us\n";

    vrrw_dmp::RolloutRequest request;
    request.goal = goal;
    request.dt = dt;
    std::size_t trajectory_points = 0;
    const double trajectory_us = medianMicroseconds(repetitions, [&] {
      const auto trajectory = dmp.rollout(request);
      trajectory_points = trajectory.points.size();
      sink = sink + trajectory.points.back().positions[0];
    });
    std::cerr << "  rollout() to a JointTrajectory (" << trajectory_points << " points incl. settling): median "
              << trajectory_us << " us\n";

    std::printf("{\"bench\":\"dmp\",\"samples\":%zu,\"dofs\":%zu,\"basis\":%zu,\"steps\":%zu,\"repetitions\":%zu,"
                "\"learn_us\":%.2f,\"rollout_us\":%.2f,\"rollout_trajectory_us\":%.2f,\"rollout_trajectory_points\":%zu,"
                "\"target_learn_us\":200,\"target_rollout_us\":100}\n",
                samples, dofs, basis, steps, repetitions, learn_us, rollout_us, trajectory_us, trajectory_points);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vrrw_bench_dmp: " << e.what() << "\n";
    return 2;
  }
}
