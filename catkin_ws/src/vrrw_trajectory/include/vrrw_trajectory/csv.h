#pragma once
#include <cstddef>
#include <iosfwd>
#include <string>

#include <vrrw_trajectory/joint_trajectory.h>
#include <vrrw_trajectory/trajectory_error.h>

namespace vrrw_trajectory
{
/// The project's one CSV layout for joint trajectories (demonstrations, recordings, DMP rollouts):
///
///     t,shoulder_pan_joint,elbow_joint,shoulder_pan_joint_vel,elbow_joint_vel
///     0,0.1,-1.2,0,0
///     0.01,0.1004,-1.199,0.04,0.1
///
/// - Row 1 is a header: `t` (or `time`), then the n joint names (positions, rad or m), then the n
///   velocity columns named `<joint>_vel` in the same order. The seed's anonymous header
///   `t,q1..qn,qd1..qdn` is accepted too (joint names become q1..qn).
/// - Optionally, named extra columns after the velocities (e.g. `gripper`, as vrrw_demos exports):
///   read into JointTrajectory::extra_names and JointTrajectory::extras, written back the same way.
/// - Then one row per sample: time in seconds, strictly increasing; every cell a finite number.
/// - At least two samples. Blank lines are ignored; cells may carry surrounding spaces; CRLF is fine.
/// - Written with the shortest decimal that reads back to the identical double.
/// Every error is a TrajectoryError whose message is one line: "FILE:LINE: reason"; it quotes at most
/// 32 characters of a cell. The input is read a line at a time, each line up to kMaxLineLength.

/// \brief The longest line read (a row of 7 joints and their velocities is about 400 characters).
constexpr std::size_t kMaxLineLength = 65536;
/// \brief The most lines read: an hour at 1 kHz is 3.6 million.
constexpr std::size_t kMaxRows = 10000000;

/// \brief Reads a trajectory CSV file (positions and velocities; no accelerations).
JointTrajectory readCsv(const std::string& path);

/// \brief Reads CSV text from a stream; \a source names it in error messages.
JointTrajectory readCsv(std::istream& in, const std::string& source);

/// \brief Writes a trajectory to a CSV file; every point needs n positions and n velocities. The file
/// appears complete or not at all (writeWholeFile).
void writeCsv(const std::string& path, const JointTrajectory& trajectory);

/// \brief Writes CSV text to a stream; \a source names it in error messages.
void writeCsv(std::ostream& out, const JointTrajectory& trajectory, const std::string& source);
}  // namespace vrrw_trajectory
