#pragma once
#include <trajectory_msgs/JointTrajectory.h>

#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_trajectory
{
/// \brief A ROS trajectory as the ROS-free type; times are time_from_start in seconds.
JointTrajectory fromMsg(const trajectory_msgs::JointTrajectory& msg);

/// \brief The ROS-free trajectory as a message (header left empty: stamp 0 means "start now").
trajectory_msgs::JointTrajectory toMsg(const JointTrajectory& trajectory);

/// \brief One point as a message point (effort left empty).
trajectory_msgs::JointTrajectoryPoint toMsg(const TrajectoryPoint& point);
}  // namespace vrrw_trajectory
