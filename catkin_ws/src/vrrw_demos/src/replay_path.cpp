#include <vrrw_demos/replay_path.h>

#include <algorithm>
#include <cmath>

#include <vrrw_demos/demo_error.h>

namespace vrrw_demos
{
namespace
{
constexpr int kSmoothingPasses = 200;

/// Binomial smoothing passes, each result clamped to [recorded - tolerance, recorded + tolerance].
std::vector<double> smooth(const std::vector<double>& recorded, double tolerance)
{
  std::vector<double> q = recorded, next = recorded;
  for (int pass = 0; pass < kSmoothingPasses; ++pass)
  {
    for (std::size_t k = 1; k + 1 < q.size(); ++k)
      next[k] = std::clamp(0.25 * (q[k - 1] + 2 * q[k] + q[k + 1]), recorded[k] - tolerance, recorded[k] + tolerance);
    q.swap(next);
  }
  return q;
}

void centralVelocities(vrrw_trajectory::JointTrajectory& trajectory)
{
  auto& points = trajectory.points;
  const std::size_t n = trajectory.joint_names.size();
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    points[k].velocities.assign(n, 0.0);
    if (k == 0 || k + 1 == points.size())
      continue;  // the controller starts and ends at rest
    const double dt = points[k + 1].time - points[k - 1].time;
    for (std::size_t j = 0; j < n; ++j)
      points[k].velocities[j] = (points[k + 1].positions[j] - points[k - 1].positions[j]) / dt;
  }
}
}  // namespace

ReplayPath replayPath(const RobotTrack& track, const ReplayOptions& options)
{
  const std::size_t n = track.joint_names.size();
  if (track.states.size() < 2)
    throw DemoError("robot '" + track.robot + "': a replay needs at least two recorded states");
  if ((!options.max_velocity.empty() && options.max_velocity.size() != n) ||
      (!options.max_acceleration.empty() && options.max_acceleration.size() != n))
    throw DemoError("robot '" + track.robot + "': limits for " + std::to_string(options.max_velocity.size()) +
                    " joints, the recording has " + std::to_string(n));
  if (!(options.speed > 0) || !(options.tolerance >= 0))
    throw DemoError("speed must be > 0 and tolerance >= 0");

  ReplayPath out;
  std::vector<std::vector<double>> smoothed(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    std::vector<double> recorded;
    for (const RobotState& state : track.states)
      recorded.push_back(state.positions[j]);
    smoothed[j] = smooth(recorded, options.tolerance);
    for (std::size_t k = 0; k < recorded.size(); ++k)
      out.max_deviation = std::max(out.max_deviation, std::abs(smoothed[j][k] - recorded[k]));
  }

  auto& trajectory = out.trajectory;
  trajectory.joint_names = track.joint_names;
  const double t0 = track.states.front().time;
  const std::size_t last = track.states.size() - 1;
  for (std::size_t k = 0; k <= last; ++k)
  {
    const double t = track.states[k].time;
    const bool keep = trajectory.points.empty() || k == last ||
                      (t - t0 - trajectory.points.back().time * options.speed >= options.min_point_spacing - 1e-9 &&
                       track.states[last].time - t >= options.min_point_spacing / 2);
    if (!keep)
      continue;
    vrrw_trajectory::TrajectoryPoint point;
    point.time = (t - t0) / options.speed;
    for (std::size_t j = 0; j < n; ++j)
      point.positions.push_back(smoothed[j][k]);
    trajectory.points.push_back(std::move(point));
  }
  centralVelocities(trajectory);

  // Uniform stretch: velocities scale with 1/s, accelerations with 1/s^2.
  auto& points = trajectory.points;
  for (std::size_t k = 0; k < points.size(); ++k)
    for (std::size_t j = 0; j < n; ++j)
    {
      if (!options.max_velocity.empty() && std::abs(points[k].velocities[j]) / options.max_velocity[j] > out.time_scale)
      {
        out.time_scale = std::abs(points[k].velocities[j]) / options.max_velocity[j];
        out.limiting = trajectory.joint_names[j] + " velocity";
      }
      if (options.max_acceleration.empty() || k == 0)
        continue;
      const double dt = points[k].time - points[k - 1].time;
      const double a = std::abs(points[k].velocities[j] - points[k - 1].velocities[j]) / dt;
      if (std::sqrt(a / options.max_acceleration[j]) > out.time_scale)
      {
        out.time_scale = std::sqrt(a / options.max_acceleration[j]);
        out.limiting = trajectory.joint_names[j] + " acceleration";
      }
    }
  if (out.time_scale > 1.0)
  {
    out.time_scale *= 1.0 + 1e-6;  // strictly inside
    for (auto& point : points)
    {
      point.time *= out.time_scale;
      for (double& v : point.velocities)
        v /= out.time_scale;
    }
  }
  return out;
}
}  // namespace vrrw_demos
