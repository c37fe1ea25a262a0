#pragma once
#include <string>
#include <vector>

namespace vrrw_trajectory
{
/// \brief One sample of a joint trajectory; times are seconds from the start.
struct TrajectoryPoint
{
  double time = 0.0;
  std::vector<double> positions;
  std::vector<double> velocities;     ///< empty when unknown
  std::vector<double> accelerations;  ///< empty when unknown
};

/// \brief A joint-space trajectory, the ROS-free twin of trajectory_msgs/JointTrajectory.
struct JointTrajectory
{
  std::vector<std::string> joint_names;
  std::vector<TrajectoryPoint> points;
  std::vector<std::string> extra_names;     ///< named values carried beside the joints (CSV columns after the velocities)
  std::vector<std::vector<double>> extras;  ///< [point][extra]: empty, or one row per point (e.g. the gripper)

  double duration() const { return points.empty() ? 0.0 : points.back().time - points.front().time; }
};
}  // namespace vrrw_trajectory
