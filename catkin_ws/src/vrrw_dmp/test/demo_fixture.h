#pragma once
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_dmp_test
{
/// The DmpError message \a action throws, or "no error".
inline std::string errorOf(const std::function<void()>& action)
{
  try
  {
    action();
  }
  catch (const vrrw_dmp::DmpError& e)
  {
    return e.what();
  }
  return "no error";
}

/// A smooth 6-joint reach of duration T that starts and ends at rest (minimum jerk plus a bump).
struct SmoothDemo
{
  double T = 2.0;
  double position(std::size_t j, double t) const
  {
    const double u = std::min(std::max(t / T, 0.0), 1.0);
    const double minimum_jerk = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
    const double bump = std::pow(std::sin(M_PI * u), 2) * std::sin(2.0 * M_PI * u);
    const double j1 = static_cast<double>(j) + 1.0;
    return 0.2 * j1 - 0.5 + (0.8 - 0.25 * j1) * minimum_jerk + 0.3 * bump * (j % 2 == 0 ? 1.0 : -0.5);
  }
  double velocity(std::size_t j, double t) const
  {
    const double h = 1e-6;
    return (position(j, t + h) - position(j, t - h)) / (2.0 * h);
  }
};

/// Samples \a demo at \a samples times jittered by +-jitter of the mean step (0 = uniform), with
/// Gaussian position noise of \a noise rad; time \a density_ratio > 1 makes the first half denser.
inline vrrw_trajectory::JointTrajectory sample(const SmoothDemo& demo, std::size_t samples, double jitter,
                                               double noise = 0.0, double density_ratio = 1.0,
                                               std::size_t dofs = 6, unsigned seed = 7)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  vrrw_trajectory::JointTrajectory trajectory;
  for (std::size_t j = 0; j < dofs; ++j)
    trajectory.joint_names.push_back("joint_" + std::to_string(j + 1));
  for (std::size_t k = 0; k < samples; ++k)
  {
    double u = static_cast<double>(k) / static_cast<double>(samples - 1);
    if (k > 0 && k + 1 < samples)
      u += jitter * uniform(random) / static_cast<double>(samples - 1);
    if (density_ratio != 1.0)
      u = (std::pow(density_ratio, u) - 1.0) / (density_ratio - 1.0);
    const double t = u * demo.T;
    vrrw_trajectory::TrajectoryPoint point;
    point.time = t;
    for (std::size_t j = 0; j < dofs; ++j)
    {
      point.positions.push_back(demo.position(j, t) + noise * gauss(random));
      point.velocities.push_back(demo.velocity(j, t));
    }
    trajectory.points.push_back(point);
  }
  return trajectory;
}

/// Root mean square over time of (rollout - demo) for joint j, on the rollout's samples within [0, T].
inline double rmse(const SmoothDemo& demo, const vrrw_trajectory::JointTrajectory& rollout, std::size_t j)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& point : rollout.points)
    if (point.time <= demo.T + 1e-12)
    {
      const double e = point.positions[j] - demo.position(j, point.time);
      sum += e * e;
      ++count;
    }
  return std::sqrt(sum / static_cast<double>(count));
}
}  // namespace vrrw_dmp_test
