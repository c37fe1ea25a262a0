#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_trajectory
{
JointTrajectory fromMsg(const trajectory_msgs::JointTrajectory& msg)
{
  JointTrajectory trajectory;
  trajectory.joint_names = msg.joint_names;
  trajectory.points.reserve(msg.points.size());
  for (const auto& in : msg.points)
    trajectory.points.push_back({ in.time_from_start.toSec(), in.positions, in.velocities, in.accelerations });
  return trajectory;
}

trajectory_msgs::JointTrajectoryPoint toMsg(const TrajectoryPoint& point)
{
  trajectory_msgs::JointTrajectoryPoint out;
  out.positions = point.positions;
  out.velocities = point.velocities;
  out.accelerations = point.accelerations;
  out.time_from_start = ros::Duration(point.time);
  return out;
}

trajectory_msgs::JointTrajectory toMsg(const JointTrajectory& trajectory)
{
  trajectory_msgs::JointTrajectory msg;
  msg.joint_names = trajectory.joint_names;
  msg.points.reserve(trajectory.points.size());
  for (const auto& point : trajectory.points)
    msg.points.push_back(toMsg(point));
  return msg;
}
}  // namespace vrrw_trajectory
