#pragma once
#include <string>

#include <vrrw_demos/demonstration.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_demos
{
/// \brief The name of the CSV column after the velocities that holds the gripper's actuated joint.
constexpr const char* kGripperColumn = "gripper";

/// \brief A track as the project's CSV layout `t, q1..qn, qd1..qdn, gripper` (vrrw_trajectory/csv.h):
/// one point per recorded state, no resampling. Throws DemoError when the track has no state.
vrrw_trajectory::JointTrajectory toTrajectory(const RobotTrack& track);

/// \brief The track of robot \a robot from a CSV trajectory; a missing `gripper` column reads as 0.
/// Throws DemoError naming \a source when a velocity is missing.
RobotTrack fromTrajectory(const vrrw_trajectory::JointTrajectory& trajectory, const std::string& robot,
                          const std::string& source);

/// \brief Bounds of an imported state (physical sanity: a UR joint turns +-2 pi; a gripper's actuated joint
/// is well inside +-pi rad or m; a value beyond is another unit or a broken file).
constexpr double kMaxJointPosition = 4 * 3.14159265358979;  ///< rad (m)
constexpr double kMaxJointVelocity = 100.0;                 ///< rad/s (m/s)
constexpr double kMaxGripperPosition = 3.14159265358979;    ///< rad (m)

/// \brief Writes the track to \a path (complete or not at all); never overwrites, never takes a recording's
/// name (refuseTaken): a DemoError.
void exportCsv(const RobotTrack& track, const std::string& path);

/// \brief Throws DemoError unless \a robot is a robot's name (a letter, then letters, digits and _).
void checkRobotName(const std::string& robot);

/// \brief Reads a track of robot \a robot from a CSV file: its joints must be the robot's (named
/// `<robot>_<joint>`; the seed's anonymous q1..qn pass, naming no robot), every value within the bounds above.
/// Errors are DemoError "FILE:LINE: reason".
RobotTrack importCsv(const std::string& path, const std::string& robot);
}  // namespace vrrw_demos
