#include <algorithm>
#include <cmath>
#include <sstream>
#include <vrrw_control/ros/msg_conversions.h>

namespace vrrw_control
{
trajectory_msgs::JointTrajectoryPoint toPointMsg(const JointSample& sample, double time_from_start)
{
  trajectory_msgs::JointTrajectoryPoint p;
  p.positions = sample.positions;
  p.velocities = sample.velocities;
  p.accelerations = sample.accelerations;
  p.time_from_start = ros::Duration(time_from_start);
  return p;
}

namespace
{
double merge(double requested, double fallback)
{
  if (requested < 0.0)
    return 0.0;
  return requested > 0.0 ? requested : fallback;
}

bool apply(const std::vector<control_msgs::JointTolerance>& given, const std::vector<std::string>& joints,
           std::vector<double>& position, std::vector<double>& velocity, std::string& error, const char* kind)
{
  for (size_t i = 0; i < given.size(); ++i)
  {
    const auto& t = given[i];
    const std::string field = std::string(kind) + "_tolerance[" + std::to_string(i) + "]";
    const auto it = std::find(joints.begin(), joints.end(), t.name);
    if (it == joints.end())
    {
      error = field + ": joint " + t.name + " is not a joint of this controller";
      return false;
    }
    for (const auto& [what, value] : { std::pair{ "position", t.position }, std::pair{ "velocity", t.velocity },
                                        std::pair{ "acceleration", t.acceleration } })
      if (!std::isfinite(value))
      {
        error = field + " (joint " + t.name + "): " + what + " is not finite";
        return false;
      }
    const size_t j = static_cast<size_t>(it - joints.begin());
    position[j] = merge(t.position, position[j]);
    velocity[j] = merge(t.velocity, velocity[j]);
  }
  return true;
}
}  // namespace

std::string applyTolerances(const std::vector<control_msgs::JointTolerance>& path,
                            const std::vector<control_msgs::JointTolerance>& goal, double goal_time,
                            const std::vector<std::string>& joints, Tolerances& tol)
{
  if (!std::isfinite(goal_time) || goal_time < 0.0)
  {
    std::ostringstream why;
    why << "goal_time_tolerance " << goal_time << " s: must be >= 0 (0: the default)";
    return why.str();
  }
  std::string error;
  if (!apply(path, joints, tol.path_position, tol.path_velocity, error, "path") ||
      !apply(goal, joints, tol.goal_position, tol.goal_velocity, error, "goal"))
    return error;
  if (goal_time > 0.0)
    tol.goal_time = goal_time;
  return "";
}
}  // namespace vrrw_control
