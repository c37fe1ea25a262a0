#pragma once
#include <string>
#include <vector>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_evaluation
{
/// \brief One instruction of a recording: seconds from the recording's start.
struct Segment
{
  std::string name;
  double start = 0.0;
  double end = 0.0;
};

/// \brief A pick-and-place as recorded: the arm's measured joints (seconds from the start), the
/// instructions' boundaries, and the gripper goals that closed and opened the hand.
struct Demonstration
{
  vrrw_trajectory::JointTrajectory arm;
  std::vector<Segment> segments;
  double finger_closed = 0.8;  ///< GripperCommand position of close_gripper
  double finger_open = 0.0;    ///< ... and of open_gripper
  double grip_force = 0.0;     ///< max_effort of close_gripper, N

  /// \brief The segment named `name`; throws std::invalid_argument naming it when absent.
  const Segment& segment(const std::string& name) const;
};

/// s: slice() leaves out recorded samples this close to its ends (the interpolated end stands for them), so
/// a goal made from it has no near-zero interval (a stamp 0.1 ms after the start would ask for any speed).
constexpr double kEndGap = 0.005;

/// \brief The samples of `trajectory` in (start, end) at least kEndGap from both, with the positions at start
/// and end interpolated as first and last point, times rebased to 0. Throws std::invalid_argument when fewer
/// than 3 points result.
vrrw_trajectory::JointTrajectory slice(const vrrw_trajectory::JointTrajectory& trajectory, double start, double end);
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
}  // namespace vrrw_evaluation
