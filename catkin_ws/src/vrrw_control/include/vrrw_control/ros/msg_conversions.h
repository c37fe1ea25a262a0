#pragma once
#include <control_msgs/JointTolerance.h>
#include <string>
#include <trajectory_msgs/JointTrajectory.h>
#include <vrrw_control/joint_sample.h>
#include <vrrw_control/tolerances.h>

namespace vrrw_control
{
/// \brief A JointSample as a trajectory point (effort left empty).
trajectory_msgs::JointTrajectoryPoint toPointMsg(const JointSample& sample, double time_from_start = 0.0);

/// \brief Applies control_msgs tolerances over `defaults`: 0 keeps the default, a negative value (-1)
/// erases the check, a positive value replaces it. Returns one line naming the field of an unknown
/// joint, a value that is not finite or a negative goal_time_tolerance, else "".
std::string applyTolerances(const std::vector<control_msgs::JointTolerance>& path,
                            const std::vector<control_msgs::JointTolerance>& goal, double goal_time,
                            const std::vector<std::string>& joints, Tolerances& defaults);
}  // namespace vrrw_control
