#pragma once
#include <string>
#include <vector>

#include <trajectory_msgs/JointTrajectory.h>

#include "vrrw_trajectory/joint_trajectory.h"

namespace vrrw_dmp
{
/// \brief time_from_start, positions and (when given) velocities of a message.
vrrw_trajectory::JointTrajectory fromMessage(const trajectory_msgs::JointTrajectory& message);

/// \brief A message ready for a FollowJointTrajectory goal (header stamp zero: start on receipt).
trajectory_msgs::JointTrajectory toMessage(const vrrw_trajectory::JointTrajectory& trajectory);

/// \brief A demonstration from a bag topic of sensor_msgs/JointState (every message that carries all
/// wanted joints is a sample; stamps, or bag times when zero; repeated times are dropped and counted in
/// \a dropped) or trajectory_msgs/JointTrajectory (the first message). Throws std::runtime_error
/// "bag PATH: reason".
vrrw_trajectory::JointTrajectory readBag(const std::string& path, const std::string& topic,
                                         const std::vector<std::string>& joint_names, std::size_t& dropped);
}  // namespace vrrw_dmp
