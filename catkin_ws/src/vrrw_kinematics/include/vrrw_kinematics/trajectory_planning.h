#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>
#include <vrrw_trajectory/joint_trajectory.h>

#include <vrrw_kinematics/contact.h>
#include <vrrw_kinematics/motion_planner.h>
#include <vrrw_kinematics/time_parameterization.h>

namespace vrrw_kinematics
{
/// \brief A motion from the start through joint-space waypoints, in order, to the goal.
/// \brief Fractions (0, 1] of the joint velocity and acceleration limits a trajectory is timed with, as
/// MoveIt's max_velocity_scaling_factor and max_acceleration_scaling_factor.
struct SpeedScaling
{
  double velocity = 1.0;
  double acceleration = 1.0;
};

/// \brief The scaling of a service request's two factors, where 0 (an unset field) means 1.
SpeedScaling speedScaling(double max_velocity_scaling_factor, double max_acceleration_scaling_factor);

struct TrajectoryRequest
{
  /// Start, goal (joint values or a pose of the planner's tip), planner, seed; time_limit covers every leg.
  PlanRequest plan;
  /// Joint values visited in order between the start and the goal; the trajectory stops at each one.
  std::vector<Eigen::VectorXd> waypoints;
  SpeedScaling scaling;
  TimeProfile profile = TimeProfile::TimeOptimal;
};

/// \brief A timed trajectory through every waypoint, or which waypoint failed and why.
struct TrajectoryResult
{
  bool success = false;
  ErrorCode code = ErrorCode::PlanningFailed;
  std::string message;  ///< one line; a waypoint's failure starts with "waypoint <i>: "
  /// The waypoint whose state or leg (the motion that leads to it) failed; waypoints.size() for the goal;
  /// -1 for the start or the request as a whole (time limit, planner name).
  int failed_waypoint = -1;
  Contact contact;  ///< on InCollision: the colliding pair
  vrrw_trajectory::JointTrajectory trajectory;  ///< at rest at the start, at every waypoint and at the goal
  std::vector<double> waypoint_times;           ///< s from the start: when each waypoint, and last the goal, is reached
  std::vector<Eigen::VectorXd> path;            ///< the checked polyline of every leg, start first
  double planning_time = 0.0;                   ///< s, every leg, timing excluded
  double path_length = 0.0;                     ///< joint space (rad, m)
};

/// \brief Appends `next`, which starts where `result` ends (both at rest): its samples shifted to `result`'s
/// end, its waypoint times, path, planning time and path length added. An empty `result` takes it whole.
void appendTrajectory(TrajectoryResult& result, const TrajectoryResult& next);

/// \brief Plans start -> waypoints -> goal leg by leg with `planner` and times each leg with `timing` (times
/// request.scaling) by request.profile: time-optimal with corners blended (TimingOptions::max_deviation)
/// unless the blended trajectory leaves the collision-free space, then stopping at every vertex of the
/// checked polyline; minimum-jerk always stops there. Legs meet at rest, exactly at the
/// waypoints, so the trajectory passes through each of them. Every waypoint is checked (size, limits,
/// collision) before any leg is planned.
TrajectoryResult planTrajectory(MotionPlanner& planner, const TimingOptions& timing, const TrajectoryRequest& request);
}  // namespace vrrw_kinematics
