#pragma once
// Joint paths as the demo measures and sends them (vrrw_trajectory::JointTrajectory); demonstrations themselves
// are vrrw_demos' (vrrw_demos/demonstration.h, read from the bag).
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_evaluation
{
/// \brief Positions at time t, linearly interpolated, clamped to the ends.
std::vector<double> positionsAt(const vrrw_trajectory::JointTrajectory& trajectory, double t);
/// \brief Root mean square over joints and samples of `reference` of the difference to `measured` at the
/// same time from its start (measured interpolated; both start at their first sample).
double jointRms(const vrrw_trajectory::JointTrajectory& reference, const vrrw_trajectory::JointTrajectory& measured);
/// \brief max_j |a_j - b_j| over the joints both have (rad).
double largestJointDifference(const std::vector<double>& a, const std::vector<double>& b);
/// \brief Velocities by central differences of the positions over time; at rest at both ends.
void addVelocities(vrrw_trajectory::JointTrajectory& trajectory);
/// \brief The samples at least `period` apart, and the last, velocities kept: a recording as one goal.
vrrw_trajectory::JointTrajectory thin(const vrrw_trajectory::JointTrajectory& trajectory, double period);
/// \brief A measured path as a vrrw_demos track of \a robot (velocities by central differences), so that the
/// demo's own recordings and the bag's are sliced one way (vrrw_demos::slice).
vrrw_demos::RobotTrack asTrack(vrrw_trajectory::JointTrajectory trajectory, const std::string& robot);
/// \brief One arm instruction of a track as a FollowJointTrajectory goal: the states of [start, end] with times
/// from 0 and velocities from the positions (at rest at both ends).
vrrw_trajectory::JointTrajectory instructionGoal(const vrrw_demos::RobotTrack& track, double start, double end);
}  // namespace vrrw_evaluation
