#include <vrrw_demos/approach_move.h>

#include <algorithm>
#include <cmath>

#include <vrrw_demos/demo_error.h>

namespace vrrw_demos
{
vrrw_trajectory::JointTrajectory approachMove(const std::vector<std::string>& joints, const std::vector<double>& from,
                                              const std::vector<double>& to, const std::vector<double>& max_velocity,
                                              const ApproachOptions& options)
{
  const std::size_t n = joints.size();
  if (from.size() != n || to.size() != n || max_velocity.size() != n)
    throw DemoError("approach: " + std::to_string(n) + " joints, but " + std::to_string(from.size()) + " start, " +
                    std::to_string(to.size()) + " goal values and " + std::to_string(max_velocity.size()) +
                    " velocity limits");
  double seconds = options.min_duration;
  for (std::size_t j = 0; j < n; ++j)
  {
    if (!(max_velocity[j] > 0.0))
      throw DemoError("approach: joint " + joints[j] + ": velocity limit " + std::to_string(max_velocity[j]) +
                      " is not positive");
    seconds = std::max(seconds, std::abs(to[j] - from[j]) / (options.velocity_fraction * max_velocity[j]));
  }
  vrrw_trajectory::JointTrajectory move;
  move.joint_names = joints;
  move.points.resize(2);
  move.points[0].positions = from;
  move.points[1].positions = to;
  move.points[1].time = seconds;
  for (auto& point : move.points)
    point.velocities.assign(n, 0.0);
  return move;
}
}  // namespace vrrw_demos
