#include <algorithm>
#include <cmath>
#include <vrrw_control/stop_trajectory.h>

namespace vrrw_control
{
vrrw_trajectory::JointTrajectory makeStopTrajectory(const std::vector<std::string>& joints, const JointSample& current,
                                                    const std::vector<double>& max_deceleration)
{
  const size_t n = current.size();
  double duration = 0.0;
  for (size_t j = 0; j < n; ++j)
    duration = std::max(duration, std::abs(current.velocities[j]) / max_deceleration[j]);

  vrrw_trajectory::JointTrajectory stop;
  stop.joint_names = joints;
  vrrw_trajectory::TrajectoryPoint from;
  from.positions = current.positions;
  from.velocities = current.velocities;
  stop.points.push_back(from);
  if (duration < 1e-9)
  {
    stop.points.front().velocities.assign(n, 0.0);
    return stop;
  }
  vrrw_trajectory::TrajectoryPoint rest;
  rest.time = duration;
  rest.velocities.assign(n, 0.0);
  for (size_t j = 0; j < n; ++j)
    rest.positions.push_back(current.positions[j] + 0.5 * current.velocities[j] * duration);
  stop.points.push_back(rest);
  return stop;
}
}  // namespace vrrw_control
